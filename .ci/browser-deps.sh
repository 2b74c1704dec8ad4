#!/usr/bin/env bash
# Install Debian's Chromium when it is missing: the browser tests drive /usr/bin/chromium
# (headless) through Playwright for Python. Never `playwright install`: no downloaded browser builds.
set -euo pipefail
if [ ! -x /usr/bin/chromium ]; then
  echo "installing Debian's chromium for the browser tests"
  SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq chromium
fi
