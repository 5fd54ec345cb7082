#!/bin/sh
# Install a Debian package unless its command is already on PATH (idempotent).
# Usage: sh .ci/apt-install.sh COMMAND PACKAGE
set -eu
cmd="$1"; pkg="$2"
if command -v "$cmd" >/dev/null 2>&1; then
    echo "$cmd already installed: $(command -v "$cmd")"
    exit 0
fi
SUDO=""
if [ "$(id -u)" -ne 0 ] && command -v sudo >/dev/null 2>&1; then
    SUDO="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q "$pkg"
command -v "$cmd"
