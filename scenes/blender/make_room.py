"""Builds issue 35's Blender test room with bpy and exports it as a Blender user would.

Run with the bpy venv (scenes/blender/make_venv.sh):
    scenes/blender/.venv-blender/bin/python scenes/blender/make_room.py [--render DIR]

A 4 x 2.6 x 4 m room without ceiling or front wall (so the sun reaches in), lit by a sun, a point
lamp 0.4 m in front of a curtain on the back wall (the shadow-acne case) and a hard spot (Blend 0,
so innerConeAngle == outerConeAngle), with a glass sphere (KHR_materials_transmission), a box, an
emissive panel and a 16:9 camera. Exported with the glTF exporter's defaults plus Lights, Cameras
and Apply Modifiers, once per lighting mode: blender_room_standard.gltf (Standard: photometric,
candela and lux) and blender_room_unitless.gltf (Unitless: W/4pi and W/m2). --render also writes
Cycles' own image of the same scene (cycles.png) for looking at next to ours (docs/scenes.md,
"Blender exports"). Test data only: vct never imports bpy.
"""
import argparse
import math
import os

import bpy

HERE = os.path.dirname(os.path.abspath(__file__))


def material(name, rgb, roughness=0.6, transmission=0.0, emission=None):
    m = bpy.data.materials.new(name)
    m.use_nodes = True
    bsdf = m.node_tree.nodes["Principled BSDF"]
    bsdf.inputs["Base Color"].default_value = (*rgb, 1.0)
    bsdf.inputs["Roughness"].default_value = roughness
    bsdf.inputs["Transmission Weight"].default_value = transmission
    if emission is not None:
        bsdf.inputs["Emission Color"].default_value = (*emission[0], 1.0)
        bsdf.inputs["Emission Strength"].default_value = emission[1]
    return m


def box(name, location, size, mat):
    bpy.ops.mesh.primitive_cube_add(size=1.0, location=location)
    obj = bpy.context.active_object
    obj.name = name
    obj.scale = size
    bpy.ops.object.transform_apply(scale=True)
    obj.data.materials.append(mat)
    return obj


def build_room():
    bpy.ops.wm.read_factory_settings(use_empty=True)
    plaster = material("Plaster", (0.8, 0.78, 0.74))
    curtain = material("Curtain", (0.6, 0.15, 0.12), roughness=0.9)
    wood = material("Wood", (0.45, 0.3, 0.18), roughness=0.5)
    glass = material("Glass", (0.95, 0.95, 0.95), roughness=0.05, transmission=1.0)
    panel = material("Panel", (0.1, 0.1, 0.1), emission=((1.0, 0.85, 0.6), 5.0))
    # Blender is Z-up; the exporter's default +Y Up turns it into glTF's Y-up.
    box("Floor", (0, 0, -0.05), (4, 4, 0.1), wood)
    box("BackWall", (0, 2.05, 1.3), (4, 0.1, 2.6), plaster)
    box("LeftWall", (-2.05, 0, 1.3), (0.1, 4, 2.6), plaster)
    box("RightWall", (2.05, 0, 1.3), (0.1, 4, 2.6), plaster)
    box("Curtain", (0.9, 1.97, 1.2), (1.4, 0.04, 1.8), curtain)
    box("Crate", (-0.8, 0.6, 0.35), (0.7, 0.7, 0.7), wood)
    box("LightPanel", (-1.98, 0.8, 1.6), (0.04, 0.8, 0.4), panel)
    bpy.ops.mesh.primitive_uv_sphere_add(radius=0.35, location=(0.5, -0.2, 0.35), segments=24, ring_count=12)
    sphere = bpy.context.active_object
    sphere.name = "GlassBall"
    sphere.data.materials.append(glass)
    bpy.ops.object.shade_smooth()
    add_lights()
    add_camera()


def add_light(name, kind, location, rotation_deg, energy, **props):
    data = bpy.data.lights.new(name, kind)
    data.energy = energy
    for k, v in props.items():
        setattr(data, k, v)
    obj = bpy.data.objects.new(name, data)
    obj.location = location
    obj.rotation_euler = [math.radians(a) for a in rotation_deg]
    bpy.context.scene.collection.objects.link(obj)


def add_lights():
    add_light("Sun", "SUN", (0, 0, 5), (35, 0, 30), 2.0)  # W/m2 (Blender's sun strength)
    add_light("CurtainLamp", "POINT", (0.9, 1.55, 1.3), (0, 0, 0), 30.0, shadow_soft_size=0.0)
    add_light("HardSpot", "SPOT", (1.2, -0.8, 2.4), (35, 0, 20), 400.0, spot_size=math.radians(40),
              spot_blend=0.0, shadow_soft_size=0.0)


def add_camera():
    cam = bpy.data.cameras.new("Camera")
    cam.lens = 24.0
    obj = bpy.data.objects.new("Camera", cam)
    obj.location = (0.0, -4.2, 1.4)
    obj.rotation_euler = (math.radians(84), 0, 0)
    bpy.context.scene.collection.objects.link(obj)
    bpy.context.scene.camera = obj
    bpy.context.scene.render.resolution_x = 1920  # 16:9, exported as aspectRatio 1.778
    bpy.context.scene.render.resolution_y = 1080


def export(path, mode):
    bpy.ops.export_scene.gltf(filepath=path, export_format="GLTF_SEPARATE", export_lights=True,
                              export_cameras=True, export_apply=True, export_import_convert_lighting_mode=mode)


def render(path, width):
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = 64
    scene.cycles.use_denoising = False
    scene.render.resolution_percentage = int(100 * width / 1920)
    scene.render.filepath = path
    bpy.ops.render.render(write_still=True)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--out", default=HERE, help="folder for the two .gltf/.bin pairs")
    parser.add_argument("--render", metavar="DIR", help="also render Cycles' image into DIR/cycles.png")
    args = parser.parse_args()
    build_room()
    export(os.path.join(args.out, "blender_room_standard.gltf"), "SPEC")
    export(os.path.join(args.out, "blender_room_unitless.gltf"), "COMPAT")
    if args.render:
        render(os.path.join(args.render, "cycles.png"), 320)


if __name__ == "__main__":
    main()
