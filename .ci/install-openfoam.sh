#!/bin/sh
# Install OpenFOAM's surface utilities (surfaceCheck) for the external-client tests.
# Idempotent: does nothing when surfaceCheck is already on PATH.
# Debian 12 / Ubuntu: package "openfoam" (OpenFOAM v1912 on Debian 12), binaries in /usr/bin,
# configuration in /usr/share/openfoam (lod2energy.openfoam sets WM_PROJECT_DIR to it).
set -eu
if command -v surfaceCheck >/dev/null 2>&1; then
    echo "surfaceCheck already installed: $(command -v surfaceCheck)"
    exit 0
fi
SUDO=""
if [ "$(id -u)" -ne 0 ] && command -v sudo >/dev/null 2>&1; then
    SUDO="sudo"
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q openfoam
command -v surfaceCheck
