# Renders an exported crowd (mobb export-crowd ... --body) headless in Blender, for docs/export.md:
#   blender -b --factory-startup --python scripts/render_crowd_blender.py -- crowd.glb out.png [SECONDS] [WIDTH HEIGHT]
#       [look=X,Y] [distance=D] [samples=N]
# Imports the GLB (one armature per agent, skinned capsule bodies, the world's walls, obstacles and goals),
# adds a ground, a sun and a camera looking down at the world from its south-west corner, and renders the
# frame at SECONDS (default 5) with Cycles on the CPU (64 samples). Debian's Blender 3.4.
# A close-up: look=X,Y (a ground point, mobb's metres: the export's glTF (x, h, -y) is Blender's (x, y, h))
# puts the camera low, D metres (default 4) south-west of it, aimed at knee height there, so feet on the
# ground can be judged; samples=N sets Cycles' samples.
import sys

import numpy

if "bool" not in vars(numpy):  # Blender 3.4's glTF importer still names numpy.bool (only ever the builtin)
    numpy.bool = bool

import bpy  # noqa: E402
from mathutils import Vector  # noqa: E402

argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
args = [a for a in argv if "=" not in a]
options = dict(a.split("=", 1) for a in argv if "=" in a)
if len(args) < 2 or not set(options) <= {"look", "distance", "samples"}:
    sys.exit("usage: blender -b --python render_crowd_blender.py -- CROWD.glb OUT.png [SECONDS] [WIDTH HEIGHT]"
             " [look=X,Y] [distance=D] [samples=N]")
glb, out = args[0], args[1]
seconds = float(args[2]) if len(args) > 2 else 5.0
width, height = (int(args[3]), int(args[4])) if len(args) > 4 else (960, 540)
look = Vector([float(v) for v in options["look"].split(",")] + [0.0]) if "look" in options else None
distance = float(options.get("distance", 4.0))
samples = int(options.get("samples", 64))

bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
scene.render.fps = 30
bpy.ops.import_scene.gltf(filepath=glb)
scene.frame_set(int(round(seconds * scene.render.fps)))
# The bodies' joints only move (the export animates positions, not rotations), so the normals stored in the
# file would stay those of the rest pose: shade from the deformed surface instead.
for o in scene.objects:
    if o.type == "MESH" and o.find_armature():
        bpy.context.view_layer.objects.active = o
        bpy.ops.mesh.customdata_custom_splitnormals_clear()
        for p in o.data.polygons:
            p.use_smooth = True

# The world's extent: every mesh's corners (the walls span it).
lo, hi = Vector((1e9, 1e9, 1e9)), Vector((-1e9, -1e9, -1e9))
for o in scene.objects:
    if o.type != "MESH":
        continue
    for c in o.bound_box:
        w = o.matrix_world @ Vector(c)
        lo = Vector(map(min, lo, w))
        hi = Vector(map(max, hi, w))
centre, size = (lo + hi) / 2, max(hi.x - lo.x, hi.y - lo.y, 1.0)

bpy.ops.mesh.primitive_plane_add(size=size * 3, location=(centre.x, centre.y, 0))
ground = bpy.context.object
mat = bpy.data.materials.new("ground")
mat.use_nodes = True
mat.node_tree.nodes["Principled BSDF"].inputs["Base Color"].default_value = (0.62, 0.62, 0.6, 1)
ground.data.materials.append(mat)

# The sun from behind the camera's left shoulder and high: lit fronts, shadows falling away from the view.
sun_from = centre + Vector((-0.2 * size, -0.9 * size, 1.2 * size))
bpy.ops.object.light_add(type="SUN", rotation=(centre - sun_from).to_track_quat("-Z", "Y").to_euler())
bpy.context.object.data.energy = 3.5
scene.world = bpy.data.worlds.new("sky")
scene.world.use_nodes = True
scene.world.node_tree.nodes["Background"].inputs["Color"].default_value = (0.75, 0.8, 0.9, 1)
scene.world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.6

if look is None:  # the whole world from above its south-west corner
    aim = centre
    eye = centre + Vector((-0.55 * size, -0.75 * size, 0.55 * size))
else:  # low, from the south-west, aimed at knee height: feet and their shadows on the ground
    aim = look + Vector((0, 0, 0.45))
    eye = look + distance * Vector((-0.55, -0.8, 0.22))
bpy.ops.object.camera_add(location=eye)
cam = bpy.context.object
cam.rotation_euler = (aim - eye).to_track_quat("-Z", "Y").to_euler()
cam.data.lens = 40 if look is None else 50
scene.camera = cam

scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.cycles.samples = samples
scene.cycles.use_denoising = False  # Debian's Blender is built without OpenImageDenoise
scene.render.resolution_x, scene.render.resolution_y = width, height
scene.render.resolution_percentage = 100
scene.render.filepath = out
bpy.ops.render.render(write_still=True)
print("MOBB rendered %s at %.2f s (frame %d)" % (out, seconds, scene.frame_current))
