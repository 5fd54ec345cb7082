#!/bin/sh
# Install OpenFOAM's utilities (surfaceCheck, blockMesh, snappyHexMesh, checkMesh, simpleFoam) for
# the external-client tests. Debian 12 / Ubuntu: package "openfoam" (OpenFOAM v1912 on Debian 12),
# binaries in /usr/bin, configuration in /usr/share/openfoam (lod2energy.openfoam sets WM_PROJECT_DIR).
set -eu
exec sh "$(dirname "$0")/apt-install.sh" surfaceCheck openfoam
