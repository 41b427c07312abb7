#!/usr/bin/env bash
# Runs the mesh generation benchmarks: 3 repetitions, aggregates only (we quote medians), JSON
# written next to the console table.
# Usage: tests/bench/run_benchmarks.sh [BUILD_DIR [OUT.json]] [--benchmark_filter=... ...]
#   BUILD_DIR defaults to build/ (the program is BUILD_DIR/bin/bench_meshgen);
#   OUT.json defaults to out/bench/bench_meshgen.json.
set -euo pipefail
cd "$(dirname "$0")/../.."

build_dir=build
out=out/bench/bench_meshgen.json
if [[ $# -gt 0 && $1 != --* ]]; then build_dir=$1; shift; fi
if [[ $# -gt 0 && $1 != --* ]]; then out=$1; shift; fi

exe="$build_dir/bin/bench_meshgen"
if [[ ! -x "$exe" ]]; then
  echo "run_benchmarks: $exe not found; build it with: cmake --build $build_dir --target bench_meshgen" >&2
  exit 1
fi
mkdir -p "$(dirname "$out")"

"$exe" \
  --benchmark_repetitions=3 \
  --benchmark_report_aggregates_only=true \
  --benchmark_out="$out" \
  --benchmark_out_format=json \
  "$@"

# Medians: one row per benchmark and N, then cells/s as a stage x N matrix.
python3 - "$out" <<'PY'
import json, sys
runs = json.load(open(sys.argv[1]))["benchmarks"]
rows = [r for r in runs if r.get("aggregate_name") == "median"]
width = max([len(r["run_name"]) for r in rows] + [20])
print(f"\n{'benchmark (median of repetitions)':<{width}} {'cells':>9} {'time/ms':>10} {'cells/s':>12}")
for r in rows:
    print(f"{r['run_name']:<{width}} {int(r.get('cells', 0)):>9d} {r['real_time']:>10.2f}"
          f" {r.get('items_per_second', 0):>12.4g}")
matrix, sizes = {}, []
for r in rows:
    name, n = r["run_name"].split("/")[:2]
    matrix.setdefault(name, {})[int(n)] = r.get("items_per_second", 0)
    if int(n) not in sizes:
        sizes.append(int(n))
sizes.sort()
print(f"\n{'median cells/s':<24}" + "".join(f" {f'N={n:.0e}':>10}" for n in sizes))
for name, by_n in matrix.items():
    print(f"{name:<24}" + "".join(f" {by_n[n] / 1e3:>9.0f}k" if n in by_n else f" {'-':>10}"
                                  for n in sizes))
print(f"\nwritten: {sys.argv[1]}")
PY
