#!/usr/bin/env bash
# Installs the Debian packages that building and testing flintstone need, if any are missing.
# The library itself needs only libc and libm; the command writes PNG through libpng; the tests
# use GMP as an independent exact oracle, g++ to check that the header compiles as C++,
# pkg-config to build the examples against an installed copy, and Chromium (headless) to open the
# HTML report the demo writes.
set -euo pipefail
packages=(gcc g++ make cmake libgmp-dev libpng-dev pkg-config chromium)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "installing: ${missing[*]}" >&2
if [ "$(id -u)" -ne 0 ]; then
  SUDO=sudo
else
  SUDO=
fi
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${missing[@]}" >/dev/null
