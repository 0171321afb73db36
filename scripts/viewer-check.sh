#!/usr/bin/env bash
# make ci-viewer, a step of make check: the real windowed viewer under Xvfb (Mesa's software
# OpenGL) renders one frame of the default scene, reads it back from the window with glReadPixels, and
# that frame must equal the headless render of the same view: same size, same settings, every
# pixel within VIEWER_TOL levels. Exits non-zero on any mismatch or when no window opens.
# Needs build/examples/{viewer,pngcmp} (make builds them first) and mk/examples.deps (xvfb,
# xauth, Mesa), which make installs for this goal.
set -euo pipefail
cd "$(dirname "$0")/.."
: "${BUILD:=build}"
SCENE=${SCENE:-examples/scenes/molecule.txt}
SIZE=${SIZE:-640x480}
# The texture is drawn 1:1 with nearest filtering, so the window shows the traced bytes
# unchanged: no level of difference is allowed.
VIEWER_TOL=0
OUT=$BUILD/examples/ci-viewer
for b in viewer pngcmp; do
  [ -x "$BUILD/examples/$b" ] || { echo "ci-viewer: $BUILD/examples/$b missing (make ci-viewer builds it)" >&2; exit 1; }
done
mkdir -p "$OUT"
rm -f "$OUT"/window.png "$OUT"/headless.png

# Xvfb picks a free display itself and writes its number to fd 3.
Xvfb -displayfd 3 -screen 0 1024x768x24 -nolisten tcp 3>"$OUT/display" 2>"$OUT/xvfb.log" &
xvfb_pid=$!
trap 'kill "$xvfb_pid" 2>/dev/null || true' EXIT
for _ in $(seq 100); do [ -s "$OUT/display" ] && break; sleep 0.1; done
if [ ! -s "$OUT/display" ]; then echo "ci-viewer: Xvfb did not start"; cat "$OUT/xvfb.log"; exit 1; fi
export DISPLAY=":$(head -n1 "$OUT/display")"
export LIBGL_ALWAYS_SOFTWARE=1
echo "ci-viewer: Xvfb on $DISPLAY; $(basename "$SCENE") at $SIZE"

# Twenty frames of the same view in the window (the log gets a windowed frames-per-second
# figure); the last is read back from OpenGL's back buffer, then the viewer quits.
# Exit code 2 is "no window could be opened": seen once in six runs right after Xvfb reported
# its display, so the window gets one more try a second later before the check fails.
for try in 1 2; do
  rc=0
  timeout 60 "$BUILD/examples/viewer" --size "$SIZE" --frames 20 --readback "$OUT/window.png" \
    "$SCENE" || rc=$?
  [ "$rc" -ne 2 ] && break
  echo "ci-viewer: no window on try $try"; sleep 1
done
if [ "$rc" -ne 0 ]; then echo "ci-viewer: FAILED: the windowed viewer exited with $rc"; exit 1; fi
"$BUILD/examples/viewer" --headless --size "$SIZE" --out "$OUT/headless.png" "$SCENE"
if "$BUILD/examples/pngcmp" "$OUT/window.png" "$OUT/headless.png" "$VIEWER_TOL" 0; then
  echo "ci-viewer: the window shows the headless render exactly"
else
  echo "ci-viewer: FAILED: the window's frame differs from the headless render ($OUT)"
  exit 1
fi
