#!/usr/bin/env bash
# Runs COMMAND (make demo's build) while install_deps.sh installs the packages of LIST_OPTION
# (--desktop: rviz, Xvfb, the plots; nothing in the build needs them) in the background, then
# waits for the install: on a bare 2-core machine the two overlap instead of adding up.
#   install_beside.sh LIST_OPTION LOG -- COMMAND...
# The install's output goes to LOG and is summed up at the end. Exits with COMMAND's code if it
# failed, else 1 if the install failed (naming the log), else 0. Without root, a sudo that would
# ask for a password asks for it once here, in the foreground, before anything starts.
set -uo pipefail
if [ $# -lt 4 ] || [ "$3" != -- ]; then
  echo "usage: $0 LIST_OPTION LOG -- COMMAND..." >&2
  exit 2
fi
LIST=$1 LOG=$2
shift 3
INSTALL=${AMIGOBOT_INSTALL_DEPS:-$(dirname "$0")/install_deps.sh}  # another one only in its test

if "$INSTALL" "$LIST" --check > /dev/null; then
  "$@"
  exit $?
fi
missing=$("$INSTALL" "$LIST" --check)
if [ "$(id -u)" -ne 0 ] && ! sudo -n true 2>/dev/null; then
  echo "deps: sudo is needed for the packages installed beside the build"
  sudo -v || { echo "deps: sudo refused; run make deps-workstation first" >&2; exit 1; }
fi
echo "$missing; installing them beside the build (log: $LOG)"
mkdir -p "$(dirname "$LOG")"
start=$(date +%s)
"$INSTALL" "$LIST" > "$LOG" 2>&1 &
install=$!

"$@"
rc=$?
if kill -0 "$install" 2>/dev/null; then
  echo "deps: the build is done; waiting for the packages installing beside it (tail -f $LOG)"
fi
wait "$install"
install_rc=$?
# apt's count line ("N newly installed") says what happened; else (a failure) the log's last line.
summary=$(grep -m1 "newly installed" "$LOG" || tail -n 1 "$LOG")
echo "deps: the packages beside the build: ${summary:0:160} (done within $(( $(date +%s) - start )) s, exit $install_rc)"
[ "$rc" -ne 0 ] && exit "$rc"
if [ "$install_rc" -ne 0 ]; then
  echo "deps: installing the packages beside the build failed (exit $install_rc); its log: $LOG" >&2
  tail -n 5 "$LOG" >&2
  exit 1
fi
exit 0
