# Renders an urbis export with Cycles on the CPU as urbis renders its scene (bench/cycles.sh):
#   blender -b --factory-startup --python bench/cycles/cycles_render.py -- CITY.glb OUT.exr W H SPP THREADS MAX_DEPTH SKY_R,G,B
# The file's camera; the sun from the asset's extras in urbis units (its irradiance as the Sun's
# strength, W/m^2 standing for urbis units) with urbis's 0.27 degree radius; a uniform world of the
# sky's radiance; emission as imported (glTF emissive strength: radiance in urbis units). Linear EXR,
# no denoising, no adaptive sampling. Prints "cycles: import S s, render S s" (wall clock).
import json
import math
import os
import sys
import time

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import numpy_compat  # noqa: F401,E402  (before the importer runs)

args = sys.argv[sys.argv.index("--") + 1:]
path, out = args[0], args[1]
width, height, spp, threads, max_depth = (int(a) for a in args[2:7])
sky = [float(v) for v in args[7].split(",")]

bpy.ops.wm.read_factory_settings(use_empty=True)
t0 = time.time()
bpy.ops.import_scene.gltf(filepath=path)
t_import = time.time() - t0
scene = bpy.context.scene

# The asset's extras land on the scene as custom properties; read them from the file's JSON chunk
# instead, which does not depend on the importer's version.
with open(path, "rb") as f:
    data = f.read()
json_length = int.from_bytes(data[12:16], "little")
asset = json.loads(data[20:20 + json_length])["asset"]["extras"]
sun_extras = asset["sun"]

scene.camera = next(o for o in scene.objects if o.type == "CAMERA")
for o in [o for o in scene.objects if o.type == "LIGHT"]:
    bpy.data.objects.remove(o, do_unlink=True)
if sun_extras["irradiance"] > 0:
    light = bpy.data.lights.new("sun", "SUN")
    light.energy = sun_extras["irradiance"]
    light.angle = math.radians(2 * 0.27)
    sun = bpy.data.objects.new("sun", light)
    scene.collection.objects.link(sun)
    # urbis: x east, y up, z south; Blender after the glTF import: x east, y north, z up.
    dx, dy, dz = sun_extras["direction"]
    d = (dx, -dz, dy)
    # A sun shines along its local -z: point local +z at the sun.
    sun.rotation_mode = "QUATERNION"
    from mathutils import Vector
    sun.rotation_quaternion = Vector(d).to_track_quat("Z", "Y")

world = bpy.data.worlds.new("sky")
world.use_nodes = True
world.node_tree.nodes["Background"].inputs["Color"].default_value = (sky[0], sky[1], sky[2], 1.0)
world.node_tree.nodes["Background"].inputs["Strength"].default_value = 1.0
scene.world = world

scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.cycles.samples = spp
scene.cycles.use_adaptive_sampling = False
scene.cycles.use_denoising = False
scene.cycles.max_bounces = max_depth
scene.cycles.diffuse_bounces = max_depth
scene.cycles.glossy_bounces = max_depth
scene.cycles.transmission_bounces = max_depth
scene.render.threads_mode = "FIXED"
scene.render.threads = threads
scene.render.resolution_x, scene.render.resolution_y = width, height
scene.render.resolution_percentage = 100
scene.render.image_settings.file_format = "OPEN_EXR"
scene.render.image_settings.color_depth = "32"
scene.render.filepath = out
t0 = time.time()
bpy.ops.render.render(write_still=True)
print(f"cycles: import {t_import:.3f} s, render {time.time() - t0:.3f} s")
