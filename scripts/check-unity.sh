#!/usr/bin/env bash
# Unity v2.6.1's published file hashes: anything else is refused.
set -euo pipefail
dir=$1
cd "$dir"
if ! sha256sum --quiet -c - <<'SUMS'
b90e735a54cf3b3765ab6caa955d11a1488ee73d9c6152cdc98576c2d17cb871  unity.c
9db174d3c2c6424fd35c0980c5941d124c5ebb0f48e8172f997a2aa9554b64ea  unity.h
fcd8b3f6b412ac0ab599547eb8a30b6d7f3f0af77aab31f7a1822a2a8fc9a2b2  unity_internals.h
SUMS
then
  echo "error: Unity sources in $dir do not match the sha256 of Unity v2.6.1; refusing to build." >&2
  exit 1
fi
