"""Records in tests/data/recorded/usd_ts_splines.json which specs curvebench's reader refuses, and why: the
"refused" reason of each channel, read from the lines "refused<TAB>NAME<TAB>REASON" that
tests/test_usd_ts.cpp prints for a refusal the file does not hold yet; a line "accepted<TAB>NAME"
(a recorded refusal the reader no longer makes) removes the channel's reason. Run after
scripts/peers/usd_ts_record.cpp has written the file:
    CURVEBENCH_SOURCE_DIR=$PWD build-test/tests/test_usd_ts |
        python3 scripts/peers/usd_ts_refusals.py tests/data/recorded/usd_ts_splines.json
"""

import json
import sys


def main():
    path = sys.argv[1]
    reasons = {}
    accepted = set()
    for line in sys.stdin:
        parts = line.rstrip("\n").split("\t")
        if len(parts) == 3 and parts[0] == "refused":
            reasons[parts[1]] = parts[2]
        elif len(parts) == 2 and parts[0] == "accepted":
            accepted.add(parts[1])
    with open(path) as f:
        doc = json.load(f)
    for c in doc["channels"]:
        if c["name"] in reasons:
            c["refused"] = reasons[c["name"]]
        elif c["name"] in accepted:
            c.pop("refused", None)
    with open(path, "w") as f:
        f.write(json.dumps(doc, indent=1) + "\n")
    print(f"{len(reasons)} refusals recorded, {len(accepted)} removed", file=sys.stderr)


if __name__ == "__main__":
    main()
