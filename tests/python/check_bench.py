#!/usr/bin/python3
"""ctest bench_counters_<program>: checks one benchmark program against the vocabulary with
report.py's validator (scripts/report_lib.py): every benchmark it registers (--benchmark_list_tests)
names a known method, peer or algorithm with known variants, and every benchmark it runs (all, or
those matching --filter: at least one per benchmark function, whose set-up is what takes time)
labels a known operation with items processed and sets only vocabulary counters.

  check_bench.py --bench EXE --out DIR [--filter REGEX] -- VOCABULARY_COMMAND...

VOCABULARY_COMMAND prints the vocabulary JSON (`curvebench list vocabulary --json`)."""
import argparse
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
import report_lib  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--bench", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--filter", default="", help="run only these benchmarks (all are still listed and named)")
    ap.add_argument("vocabulary_command", nargs="+")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    name = os.path.basename(a.bench)
    vocab_path = os.path.join(a.out, f"{name}.vocabulary.json")
    with open(vocab_path, "w", encoding="utf-8") as f:
        subprocess.run(a.vocabulary_command, stdout=f, check=True)
    listed = subprocess.run([a.bench, "--benchmark_list_tests=true"], stdout=subprocess.PIPE, text=True,
                            check=True).stdout.split()
    out = os.path.join(a.out, f"{name}.json")
    # The shortest run that still runs each benchmark once (set-up and counters included).
    run = [a.bench, "--benchmark_min_time=0.001", f"--benchmark_out={out}", "--benchmark_out_format=json"]
    if a.filter:
        run.append(f"--benchmark_filter={a.filter}")
    subprocess.run(run, stdout=subprocess.DEVNULL, check=True)
    try:
        vocab = report_lib.load_vocabulary(vocab_path)
        for b in listed:
            report_lib.parse_benchmark_name(b, vocab)
        n = report_lib.validate_files(vocab_path, [out])
    except report_lib.ReportError as e:
        print(f"check_bench: {e}", file=sys.stderr)
        return 1
    print(f"check_bench: {name}: {len(listed)} names and {n} runs (labels, items, counters) in the vocabulary")
    return 0


if __name__ == "__main__":
    sys.exit(main())
