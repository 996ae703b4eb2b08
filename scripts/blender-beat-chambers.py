"""A heart's four chambers beating at 72 bpm, key-framed in Blender as an animator would do it.

Run inside Blender (Debian's `blender`, 3.4):

    blender -b --factory-startup --python scripts/blender-beat-chambers.py -- HEART.glb OUT.glb [PREFIX]

Reads a heart GLB whose chambers are meshes named PREFIX + left_cardiac_atrium,
right_cardiac_atrium, heart_left_ventricle and heart_right_ventricle (the HuBMAP atlas
heart's names with PREFIX "VH_M_", the default), gives each chamber one shape key that
draws every vertex towards the chamber's centroid, keys its weight over one beat (the atria
first, the ventricles from 160 ms on, each with the ease in and out of Blender's default
Bezier keys; the septum and the papillary muscles move with their ventricle), and exports the result as a GLB with morph targets and one looping animation.
The valves stay still. `systole tune` takes the
file as an organ's `target.animation` (docs/training.md, "A target of any mesh").

The beat (72 bpm, 0.833 s; 60 key frames a second, 50 a beat): the atria contract by 10 %
of each vertex's distance from their centroid over 0-150 ms (peak at 70 ms), the ventricles
by 15 % (left) and 13 % (right) over 160-500 ms (peak at 360 ms): the timing of
scenes/heart.yaml's drives (systolic fractions 0.15 and 0.36 after a 160-ms AV delay).
"""
import sys

import bpy
import numpy

# Blender 3.4's glTF importer still names numpy.bool, which numpy 1.24 removed.
if not hasattr(numpy, "bool"):
    numpy.bool = bool

FPS = 60
BEAT_FRAMES = 50  # 60 / 72 s at 60 frames a second.
# Chamber: (shape key's pull towards the centroid, keys as (frame, weight)).
ATRIUM_KEYS = [(0, 0.0), (4, 1.0), (9, 0.0), (BEAT_FRAMES, 0.0)]
VENTRICLE_KEYS = [(0, 0.0), (10, 0.0), (22, 1.0), (30, 0.0), (BEAT_FRAMES, 0.0)]
CHAMBERS = {
    "left_cardiac_atrium": (0.10, ATRIUM_KEYS),
    "right_cardiac_atrium": (0.10, ATRIUM_KEYS),
    "heart_left_ventricle": (0.15, VENTRICLE_KEYS),
    "heart_right_ventricle": (0.13, VENTRICLE_KEYS),
}
# Parts inside a ventricle's wall move with it, drawn towards its centroid with its key: the
# septum and the left papillary muscles with the left ventricle, the right ones with the right.
WITH_VENTRICLE = {
    "interventricular_septum": "heart_left_ventricle",
    "papillary_muscle_of_heart_anterolateral": "heart_left_ventricle",
    "papillary_muscle_of_heart_posteromedial": "heart_left_ventricle",
    "papillary_muscle_of_heart_anterior": "heart_right_ventricle",
    "papillary_muscle_of_heart_posterior": "heart_right_ventricle",
    "papillary_muscle_of_heart_medial": "heart_right_ventricle",
}


def centroid_of(ob):
    """The mesh's vertex centroid in world coordinates."""
    return sum((ob.matrix_world @ v.co for v in ob.data.vertices), start=ob.matrix_world.translation * 0) / len(ob.data.vertices)


def beat_part(ob, towards, pull, keys):
    """One shape key drawing the mesh towards the world point `towards` by `pull`, keyed over the beat."""
    ob.shape_key_add(name="Basis")
    key = ob.shape_key_add(name="beat")
    local = ob.matrix_world.inverted() @ towards
    for v in key.data:
        v.co = local + (v.co - local) * (1.0 - pull)
    for frame, weight in keys:
        key.value = weight
        key.keyframe_insert("value", frame=frame)


def main():
    argv = sys.argv[sys.argv.index("--") + 1:]
    src, dst = argv[0], argv[1]
    prefix = argv[2] if len(argv) > 2 else "VH_M_"
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.gltf(filepath=src)
    scene = bpy.context.scene
    scene.render.fps = FPS
    scene.frame_start, scene.frame_end = 0, BEAT_FRAMES
    meshes = {ob.name[len(prefix):]: ob for ob in bpy.data.objects if ob.type == "MESH" and ob.name.startswith(prefix)}
    found = [prefix + c for c in CHAMBERS if c in meshes]
    centroids = {c: centroid_of(meshes[c]) for c in CHAMBERS if c in meshes}
    for c, (pull, keys) in CHAMBERS.items():
        if c in meshes:
            beat_part(meshes[c], centroids[c], pull, keys)
    for part, ventricle in WITH_VENTRICLE.items():
        if part in meshes and ventricle in centroids:
            beat_part(meshes[part], centroids[ventricle], *CHAMBERS[ventricle])
    missing = sorted(set(prefix + c for c in CHAMBERS) - set(found))
    if missing:
        sys.exit("blender-beat-chambers: no mesh named " + ", ".join(missing) + " in " + src)
    bpy.ops.export_scene.gltf(filepath=dst, export_format="GLB", export_animations=True, export_morph=True,
                              export_morph_normal=False, export_nla_strips=False, export_force_sampling=True,
                              export_frame_range=True)
    print("blender-beat-chambers: wrote", dst, "with", ", ".join(sorted(found)), "beating")


main()
