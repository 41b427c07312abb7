#!/bin/bash
# qhull_voronoi_check.sh: vorodg reads and solves a Voronoi mesh made "elsewhere" with Qhull.
#
# Generates a raw bounded Voronoi mesh (scipy/Qhull, d = 0.1, 1 Lloyd step, short edges kept) with
# scripts/qhull_voronoi_mesh.py, checks it with `vorodg mesh --check` and runs the patch and
# patch-mixed tests with dg-sipg; fails (exit 1) unless each reports an L2 error below 1e-10.
#
# Usage: qhull_voronoi_check.sh VORODG SCRATCH_DIR
set -u
if [ $# -ne 2 ]; then echo "usage: $0 VORODG SCRATCH_DIR" >&2; exit 2; fi
vorodg=$1 scratch=$2 tol=1e-10
here=$(cd "$(dirname "$0")" && pwd)
domain=0,-0.5,4,0.5
mesh=$scratch/qhull_voronoi.vtu
mkdir -p "$scratch" || exit 1

/usr/bin/python3 "$here/../../scripts/qhull_voronoi_mesh.py" -o "$mesh" --domain $domain \
  --d 0.1 --lloyd 1 --seed 1 || { echo "FAIL: mesh generation"; exit 1; }
"$vorodg" mesh --check "$mesh" --domain $domain || { echo "FAIL: mesh --check"; exit 1; }

status=0
for problem in patch patch-mixed; do
  # The summary line reads "<problem> on file: N cells, ..., L2 error X, energy error Y, rcond Z".
  out=$("$vorodg" solve --mesh "$mesh" --domain $domain --problem $problem --formulation dg-sipg \
        --threads 1 2>&1)
  rc=$?
  err=$(printf '%s\n' "$out" | sed -n 's/.* on file: .*L2 error \([^,]*\),.*/\1/p' | head -n 1)
  # A number (not nan/inf) below the tolerance, with exit code 0.
  if [ $rc -eq 0 ] && [[ $err =~ ^[0-9.]+(e[-+]?[0-9]+)?$ ]] &&
     awk -v e="$err" -v t=$tol 'BEGIN { exit !(e + 0 < t + 0) }'; then
    echo "ok   $problem dg-sipg: L2 error $err"
  else
    echo "FAIL $problem dg-sipg: exit $rc, L2 error '${err}'"; printf '%s\n' "$out" | tail -n 3
    status=1
  fi
done
exit $status
