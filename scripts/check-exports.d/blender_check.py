"""Blender (blender -b --python blender_check.py -- SPEC.json): imports Systole's exports.

For each GLB: the organ's object has the shape keys of its morph targets and an action
with one key per animation key. For each PC2/MDD: the rest OBJ with a Mesh Cache modifier
gives, at chosen frames, the positions Systole simulated (its bake) to float precision.
Prints one line per check and exits 1 if any fails.
"""
import json
import sys

# Debian 12's Blender 3.4 glTF importer calls numpy.bool, which numpy 1.24 removed.
import numpy
numpy.bool = bool

import bpy  # noqa: E402

sys.path.insert(0, __file__.rsplit('/', 1)[0])
from bake import read_bake  # noqa: E402

spec = json.load(open(sys.argv[sys.argv.index('--') + 1]))
failures = 0


def report(ok, text):
    global failures
    print(('PASS ' if ok else 'FAIL ') + text, flush=True)
    failures += 0 if ok else 1


def reset(fps):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.context.scene.render.fps = int(round(fps))
    bpy.context.scene.render.fps_base = 1


for g in spec.get('glb', []):
    reset(g['fps'])
    bpy.ops.import_scene.gltf(filepath=g['file'])
    obj = bpy.data.objects.get(g['organ'])
    if obj is None or obj.type != 'MESH':
        report(False, '%s: no mesh object named %s (objects: %s)' % (g['file'], g['organ'], list(bpy.data.objects.keys())))
        continue
    blocks = obj.data.shape_keys.key_blocks if obj.data.shape_keys else []
    targets = len(blocks) - 1 if blocks else 0
    anim = obj.data.shape_keys.animation_data if obj.data.shape_keys else None
    action = anim.action if anim else None
    keys = len(action.fcurves[0].keyframe_points) if action and action.fcurves else 0
    span = (action.frame_range[1] - action.frame_range[0]) if action else -1
    ok = targets == g['targets'] and action is not None and keys == g['keys'] and abs(span - (g['keys'] - 1)) < 1e-3
    report(ok, '%s: %d vertices, %d shape keys (expected %d), action %s with %d keys over %.1f frames (expected %d keys)'
           % (g['file'], len(obj.data.vertices), targets, g['targets'], action.name if action else None, keys, span,
              g['keys']))

for c in spec.get('caches', []):
    fps, bake = read_bake(c['bake'])
    reset(fps)
    # No axis conversion: the OBJ and the cache are both Systole's metres, Y up.
    bpy.ops.wm.obj_import(filepath=c['obj'], forward_axis='Y', up_axis='Z')
    obj = bpy.context.selected_objects[0]
    mod = obj.modifiers.new('systole', 'MESH_CACHE')
    mod.cache_format = c['format']
    mod.filepath = c['file']
    mod.forward_axis = 'POS_Y'
    mod.up_axis = 'POS_Z'
    mod.frame_start = 0
    frames = bake[c['organ']]
    worst = 0.0
    for f in c['frames']:
        bpy.context.scene.frame_set(f)
        evaluated = obj.evaluated_get(bpy.context.evaluated_depsgraph_get())
        mesh = evaluated.to_mesh()
        co = numpy.empty(3 * len(mesh.vertices))
        mesh.vertices.foreach_get('co', co)
        evaluated.to_mesh_clear()
        expected = numpy.array(frames[f])
        if co.shape != expected.shape:
            report(False, '%s: Blender has %d vertices, Systole %d' % (c['file'], co.size // 3, expected.size // 3))
            worst = float('inf')
            break
        worst = max(worst, float(numpy.abs(co - expected).max()))
    moved = float(numpy.abs(numpy.array(frames[c['frames'][-1]]) - numpy.array(frames[c['frames'][0]])).max())
    report(worst < 1e-6 and moved > 1e-5,
           '%s (%s, Mesh Cache modifier on %s): frames %s, max |Blender - Systole| %.3g m (the organ moves %.3g m)'
           % (c['file'], c['format'], c['obj'], c['frames'], worst, moved))

sys.exit(1 if failures else 0)
