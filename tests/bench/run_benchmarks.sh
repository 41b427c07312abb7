#!/usr/bin/env bash
# Runs the benchmark suite (mesh generation, element layer, CG pipeline, DG iterations) from 1e3
# to 1e6 cells: 3 repetitions where a case takes under a few seconds (the 1e6 cases once),
# aggregates only (we quote medians), JSON per program in OUT_DIR, then the Markdown tables of
# scripts/bench_table.py (machine, date, medians, counters) in OUT_DIR/tables.md.
# Usage: tests/bench/run_benchmarks.sh [BUILD_DIR [OUT_DIR]] [PROGRAM ...]
#   BUILD_DIR defaults to build/, OUT_DIR to out/bench/, PROGRAMs to all five:
#   bench_meshgen bench_element bench_cg bench_dg bench_fracture.
set -euo pipefail
cd "$(dirname "$0")/../.."

build_dir=build
out_dir=out/bench
if [[ $# -gt 0 && $1 != bench_* ]]; then build_dir=$1; shift; fi
if [[ $# -gt 0 && $1 != bench_* ]]; then out_dir=$1; shift; fi
programs=("$@")
((${#programs[@]})) || programs=(bench_meshgen bench_element bench_cg bench_dg bench_fracture)
mkdir -p "$out_dir"

jsons=()
for p in "${programs[@]}"; do
  exe="$build_dir/bin/$p"
  if [[ ! -x "$exe" ]]; then
    echo "run_benchmarks: $exe not found; build it with: cmake --build $build_dir --target $p" >&2
    exit 1
  fi
  echo "== $p"
  "$exe" --benchmark_repetitions=3 --benchmark_report_aggregates_only=true \
    --benchmark_out="$out_dir/$p.json" --benchmark_out_format=json
  jsons+=("$out_dir/$p.json")
done
PY=/usr/bin/python3
[[ -x $PY ]] || PY=python3
"$PY" scripts/bench_table.py "${jsons[@]}" > "$out_dir/tables.md"
echo "written: ${jsons[*]} $out_dir/tables.md"
