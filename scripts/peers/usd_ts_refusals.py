"""Records in tests/data/recorded/usd_ts_splines.json which specs curvebench's reader refuses, and why: the
"refused" reason of each channel, read from the lines "refused<TAB>NAME<TAB>REASON" that
tests/test_usd_ts.cpp prints for a refusal the file does not hold yet. Run after
scripts/peers/usd_ts_record.cpp has written the file:
    build-test/tests/test_usd_ts | python3 scripts/peers/usd_ts_refusals.py tests/data/recorded/usd_ts_splines.json
"""

import json
import sys


def main():
    path = sys.argv[1]
    reasons = {}
    for line in sys.stdin:
        parts = line.rstrip("\n").split("\t")
        if len(parts) == 3 and parts[0] == "refused":
            reasons[parts[1]] = parts[2]
    with open(path) as f:
        doc = json.load(f)
    for c in doc["channels"]:
        if c["name"] in reasons:
            c["refused"] = reasons[c["name"]]
    with open(path, "w") as f:
        f.write(json.dumps(doc, indent=1) + "\n")
    print(f"{len(reasons)} refusals recorded", file=sys.stderr)


if __name__ == "__main__":
    main()
