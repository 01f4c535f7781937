#!/usr/bin/env bash
# Run inside xvfb-run: runs COMMAND... once the X server on $DISPLAY answers.
set -euo pipefail
# shellcheck source=x11_window.sh
source "$(dirname "$0")/x11_window.sh"
wait_display
exec "$@"
