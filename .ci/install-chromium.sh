#!/bin/sh
# Install headless Chromium (Debian package "chromium", /usr/bin/chromium) for the browser tests of
# report.html; the tests drive it with playwright's Python client (no `playwright install`).
set -eu
exec sh "$(dirname "$0")/apt-install.sh" chromium chromium
