#!/usr/bin/env bash
# Fetch Unity's three source files from a pinned registry package (never vendored), then let
# check-unity.sh compare them with the hashes of Unity release v2.6.1.
set -euo pipefail
pkg=$1; dest=$2
dl="$dest.download"
rm -rf "$dl" && mkdir -p "$dl" "$dest"
python3 -m pip download --quiet --no-deps --disable-pip-version-check "$pkg" -d "$dl"
wheel=$(ls "$dl"/*.whl)
python3 - "$wheel" "$dest" <<'PY'
import sys, zipfile
wheel, dest = sys.argv[1], sys.argv[2]
with zipfile.ZipFile(wheel) as z:
    for name in ("unity.c", "unity.h", "unity_internals.h"):
        with open(f"{dest}/{name}", "wb") as out:
            out.write(z.read(f"vyperling/c/{name}"))
PY
bash "$(dirname "$0")/check-unity.sh" "$dest" || { rm -f "$dest"/unity*; exit 1; }
