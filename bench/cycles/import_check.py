# Blender headless import of an urbis export: `blender -b --python-exit-code 1 --python
# bench/cycles/import_check.py -- FILE.glb|.gltf|.obj`. Prints one line
# "import_check: MESHES meshes, MATERIALS materials, CAMERAS cameras, LIGHTS lights, TRIANGLES triangles"
# and exits non-zero when the importer fails or brings in no mesh (tests/export_cli_test.cpp reads it).
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import numpy_compat  # noqa: F401,E402  (before the importer runs)

path = sys.argv[sys.argv.index("--") + 1]
bpy.ops.wm.read_factory_settings(use_empty=True)
if path.lower().endswith(".obj"):
    bpy.ops.import_scene.obj(filepath=path)
else:
    bpy.ops.import_scene.gltf(filepath=path)
meshes = [o for o in bpy.context.scene.objects if o.type == "MESH"]
triangles = 0
for o in meshes:
    o.data.calc_loop_triangles()
    triangles += len(o.data.loop_triangles)
cameras = sum(1 for o in bpy.context.scene.objects if o.type == "CAMERA")
lights = sum(1 for o in bpy.context.scene.objects if o.type == "LIGHT")
print(f"import_check: {len(meshes)} meshes, {len(bpy.data.materials)} materials, {cameras} cameras, "
      f"{lights} lights, {triangles} triangles")
if not meshes:
    sys.exit(1)
