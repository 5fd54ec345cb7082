#!/bin/sh
# Install headless Chromium (Debian package) for the browser tests of report.html.
# Idempotent: does nothing when chromium is already on PATH.
# Debian 12 / Ubuntu: package "chromium", binary /usr/bin/chromium. The tests drive it with
# playwright's Python client (executable_path=/usr/bin/chromium; no `playwright install`).
set -eu
if command -v chromium >/dev/null 2>&1; then
    echo "chromium already installed: $(command -v chromium)"
    exit 0
fi
SUDO=""
if [ "$(id -u)" -ne 0 ] && command -v sudo >/dev/null 2>&1; then
    SUDO="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q chromium
command -v chromium
