"""Writes the request behind tests/data/blender_easing.json: every Penner easing family x ease mode
(Blender's AUTO included) on one segment, with default and non-default back, amplitude and period
(0 included), at times across the segment and next to its ends.

Regenerate the fixture (Blender 3.4.1 from Debian bookworm was used):
    python3 scripts/peers/blender_easing_request.py > /tmp/blender_easing_request.json
    blender -b --factory-startup --python scripts/peers/blender_fcurves.py -- \
        /tmp/blender_easing_request.json tests/data/blender_easing.json
"""

import json
import sys

FAMILIES = ("SINE", "QUAD", "CUBIC", "QUART", "QUINT", "EXPO", "CIRC", "BACK", "BOUNCE", "ELASTIC")
EASINGS = ("AUTO", "EASE_IN", "EASE_OUT", "EASE_IN_OUT")
COMMAND = ("python3 scripts/peers/blender_easing_request.py > /tmp/blender_easing_request.json && "
           "blender -b --factory-startup --python scripts/peers/blender_fcurves.py -- "
           "/tmp/blender_easing_request.json tests/data/blender_easing.json")

# Segments: (start frame, start value, end frame, end value). The first is the common case; the
# second has a falling value and a short, non-integer duration; the third a change smaller than the
# default elastic amplitude (0.8), which takes Penner's other amplitude branch; the fourth no change
# at all (elastic still oscillates there when the amplitude is not 0).
SEGMENTS = ((1.0, 2.0, 21.0, 7.0), (-3.0, 4.0, 2.5, 1.0), (0.0, 0.0, 10.0, 0.5), (0.0, 1.0, 8.0, 1.0))

# Per-family parameter sets. {} leaves what keyframe_points.add() gives: back, amplitude and period
# all 0. Inserting a key from the UI or with keyframe_insert() gives back 1.70158, amplitude 0.8 and
# period 4.1 (Blender 3.4.1), the first set of each family below.
PARAMS = {"BACK": ({"back": 1.70158}, {"back": 3.0}, {}),
          "ELASTIC": ({"amplitude": 0.8, "period": 4.1}, {}, {"amplitude": 0.0, "period": 4.1},
                      {"amplitude": 0.8, "period": 0.0}, {"amplitude": 10.0, "period": 3.0},
                      {"amplitude": 2.0, "period": 7.0}, {"amplitude": 4.0, "period": -2.0})}


def times(t0, t1):
    d = t1 - t0
    ts = [t0 + d * i / 32 for i in range(33)]
    # next to the ends (expo's and elastic's endpoint handling) and the midpoint (in_out's switch)
    ts += [t0 + d * 2.0 ** -12, t0 + d * 2.0 ** -6, t1 - d * 2.0 ** -12, t1 - d * 2.0 ** -6,
           t0 + d * (0.5 - 2.0 ** -12), t0 + d * (0.5 + 2.0 ** -12)]
    return sorted(ts)


def request():
    channels = []
    for fam in FAMILIES:
        for easing in EASINGS:
            for si, (t0, v0, t1, v1) in enumerate(SEGMENTS):
                for params in PARAMS.get(fam, ({},)):
                    name = f"{fam.lower()}/{easing.lower()}/segment{si}" + "".join(
                        f"/{k}={v}" for k, v in sorted(params.items()))
                    k0 = {"time": t0, "value": v0, "interpolation": fam, "easing": easing}
                    k0.update(params)
                    k1 = {"time": t1, "value": v1, "interpolation": fam, "easing": easing}
                    channels.append({"name": name, "keys": [k0, k1], "times": times(t0, t1)})
    return {"note": "recorded output of real Blender; regenerate with: " + COMMAND, "channels": channels}


if __name__ == "__main__":
    json.dump(request(), sys.stdout, indent=1)
    sys.stdout.write("\n")
