# Opens a VDB in Blender headless and reports how Blender places it, as an independent check that
# `vox export --for blender` comes out upright and that Volume to Mesh can use its 'density' grid:
#   blender -b --python tools/blender_upright_check.py -- out.vdb
# Prints the grids Blender sees, the volume's extent per axis (Blender is Z-up: a tower exported
# with --for blender is tallest along z) and the mesh Volume to Mesh makes from 'density'.
import sys

import bpy
from mathutils import Vector

path = sys.argv[sys.argv.index("--") + 1] if "--" in sys.argv else None
if not path:
    sys.exit("usage: blender -b --python tools/blender_upright_check.py -- FILE.vdb")

bpy.ops.object.select_all(action="SELECT")
bpy.ops.object.delete()
bpy.ops.object.volume_import(filepath=path)
volume = bpy.context.active_object
volume.data.grids.load()
grids = [g.name for g in volume.data.grids]
corners = [volume.matrix_world @ Vector(c) for c in volume.bound_box]
extent = [max(c[i] for c in corners) - min(c[i] for c in corners) for i in range(3)]
print(f"grids   {', '.join(grids)}")
print(f"extent  x {extent[0]:.1f}  y {extent[1]:.1f}  z {extent[2]:.1f}  (Blender's up is z)")

if "density" in grids:
    bpy.ops.mesh.primitive_cube_add()
    target = bpy.context.active_object
    modifier = target.modifiers.new("to_mesh", "VOLUME_TO_MESH")
    modifier.object = volume
    modifier.grid_name = "density"
    evaluated = target.evaluated_get(bpy.context.evaluated_depsgraph_get())
    mesh = evaluated.to_mesh()
    points = [evaluated.matrix_world @ v.co for v in mesh.vertices]
    if points:
        size = [max(p[i] for p in points) - min(p[i] for p in points) for i in range(3)]
        print(f"mesh    {len(points)} vertices from 'density', extent x {size[0]:.1f}  y {size[1]:.1f}  z {size[2]:.1f}")
    else:
        print("mesh    Volume to Mesh made no vertices from 'density'")
else:
    print("mesh    no 'density' grid (export with --for blender or --for houdini)")
