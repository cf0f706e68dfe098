"""A scene keyed as an animator keys one, for the test of scripts/blender_export.py.

Run inside Blender:  blender -b --factory-startup --python tests/blender/make_scene.py -- OUT.blend

Keys are inserted with keyframe_insert (Blender's defaults: Bezier, auto-clamped handles,
continuous-acceleration smoothing), then some are changed the ways the UI changes them: an eased
segment of each kind, vector and free handles, linear extrapolation, a Cycles modifier, a constant
and a linear segment, and one F-curve with a Noise modifier (which the exporter must skip).
"""

import sys

import bpy


def keyed(name, frames_values, path="location", index=0):
    obj = bpy.data.objects.new(name, None)
    bpy.context.scene.collection.objects.link(obj)
    for frame, value in frames_values:
        getattr(obj, path)[index] = value
        obj.keyframe_insert(data_path=path, index=index, frame=frame)
    return obj, obj.animation_data.action.fcurves.find(path, index=index)


def main():
    out = sys.argv[sys.argv.index("--") + 1]
    scene = bpy.context.scene
    scene.frame_start, scene.frame_end = 1, 48
    # Blender's defaults: auto-clamped Bezier keys.
    keyed("bounce", [(1, 0), (12, 4), (24, 1), (36, 3.5), (48, 0)])
    # One segment of each easing kind after the first key, alternating the easing mode.
    eased = ["SINE", "QUAD", "CUBIC", "QUART", "QUINT", "EXPO", "CIRC", "BACK", "BOUNCE", "ELASTIC"]
    _, fc = keyed("eases", [(1 + 4 * i, (i % 3) - 1) for i in range(len(eased) + 1)], "location", 1)
    for i, kind in enumerate(eased):
        kp = fc.keyframe_points[i]
        kp.interpolation = kind
        kp.easing = ("EASE_IN", "EASE_OUT", "EASE_IN_OUT", "AUTO")[i % 4]
    fc.keyframe_points[7].back = 2.5
    fc.keyframe_points[9].amplitude, fc.keyframe_points[9].period = 1.5, 3.0
    # Vector and free handles, linear extrapolation.
    _, fc = keyed("handles", [(1, 0), (10, 2), (20, -1), (30, 0.5)], "location", 2)
    fc.keyframe_points[1].handle_left_type = "VECTOR"
    fc.keyframe_points[1].handle_right_type = "VECTOR"
    kp = fc.keyframe_points[2]
    kp.handle_left_type, kp.handle_right_type = "FREE", "FREE"
    kp.handle_left, kp.handle_right = (17.0, -3.0), (24.0, 0.0)
    fc.extrapolation = "LINEAR"
    fc.update()
    # Auto handles without clamping, no smoothing, a constant and a linear segment.
    _, fc = keyed("steps", [(1, 0), (8, 5), (16, 2), (24, 6), (32, 0)], "rotation_euler", 2)
    fc.auto_smoothing = "NONE"
    for kp in fc.keyframe_points:
        kp.handle_left_type = kp.handle_right_type = "AUTO"
    fc.keyframe_points[1].interpolation = "CONSTANT"
    fc.keyframe_points[2].interpolation = "LINEAR"
    fc.update()
    # A walk cycle: a few keys and a Cycles modifier repeating on both sides.
    _, fc = keyed("cycle", [(1, 0), (7, 1), (13, 0)], "location", 0)
    fc.modifiers.new("CYCLES")
    _, fc = keyed("cycle_offset", [(1, 0), (5, 2), (9, 1)], "scale", 1)
    m = fc.modifiers.new("CYCLES")
    m.mode_before, m.mode_after = "REPEAT_OFFSET", "MIRROR"
    # A Noise modifier: not modelled, so skipped by the exporter.
    _, fc = keyed("noisy", [(1, 0), (48, 1)], "location", 0)
    fc.modifiers.new("NOISE")
    bpy.ops.wm.save_as_mainfile(filepath=out)


main()
