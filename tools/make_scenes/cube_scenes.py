"""What the scene generators share: one unit cube in a glTF buffer, instanced by nodes (a floor and
the scene's boxes or bars), and the files of a scene (SCENE.json, .gltf, .bin) written the same way.

make_occluder_scenes.py, make_point_cage.py, make_lights_scenes.py and make_gltf_lights_scene.py
beside it import it; standard library only.
"""
import json
import os
import re
import struct


def cube_buffer():
    """The unit cube ([-0.5, 0.5]^3): 24 vertices (normal and uv per face), 36 16-bit indices."""
    positions, normals, uvs, indices = [], [], [], []
    for axis in range(3):
        for sign in (-1.0, 1.0):
            n = [0.0, 0.0, 0.0]
            n[axis] = sign
            a, b = (axis + 1) % 3, (axis + 2) % 3
            if sign < 0:
                a, b = b, a  # keep the winding counter-clockwise seen from outside
            base = len(positions)
            for (u, v) in ((-0.5, -0.5), (0.5, -0.5), (0.5, 0.5), (-0.5, 0.5)):
                p = [0.0, 0.0, 0.0]
                p[axis] = 0.5 * sign
                p[a] = u
                p[b] = v
                positions.append(p)
                normals.append(n)
                uvs.append([u + 0.5, v + 0.5])
            indices += [base, base + 1, base + 2, base, base + 2, base + 3]
    data = b"".join(struct.pack("<3f", *p) for p in positions)
    data += b"".join(struct.pack("<3f", *n) for n in normals)
    data += b"".join(struct.pack("<2f", *t) for t in uvs)
    data += b"".join(struct.pack("<H", i) for i in indices)
    data += b"\0" * (-len(data) % 4)
    return data, len(positions), len(indices)


def compact(text):
    """json.dumps(indent=...) text with arrays of plain numbers on one line each."""
    return re.sub(r"\[\s*([-0-9.e+,\s]*?)\s*\]",
                  lambda m: "[" + ", ".join(x.strip() for x in m.group(1).split(",")) + "]", text)


def r6(x):
    return round(x, 6)


def cube_mesh_layout(vertex_count, index_count):
    """The accessors, buffer views and attributes of cube_buffer()'s data: positions, normals,
    texture coordinates, then 16-bit indices, one after another in one buffer."""
    v = vertex_count
    accessors = [
        {"bufferView": 0, "componentType": 5126, "count": v, "type": "VEC3",
         "min": [-0.5, -0.5, -0.5], "max": [0.5, 0.5, 0.5]},
        {"bufferView": 1, "componentType": 5126, "count": v, "type": "VEC3"},
        {"bufferView": 2, "componentType": 5126, "count": v, "type": "VEC2"},
        {"bufferView": 3, "componentType": 5123, "count": index_count, "type": "SCALAR"},
    ]
    views = [
        {"buffer": 0, "byteOffset": 0, "byteLength": 12 * v, "target": 34962},
        {"buffer": 0, "byteOffset": 12 * v, "byteLength": 12 * v, "target": 34962},
        {"buffer": 0, "byteOffset": 24 * v, "byteLength": 8 * v, "target": 34962},
        {"buffer": 0, "byteOffset": 32 * v, "byteLength": 2 * index_count, "target": 34963},
    ]
    return accessors, views, {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}


def material(name, rgb, roughness):
    """A matte glTF material (metallic 0)."""
    return {"name": name, "pbrMetallicRoughness": {"baseColorFactor": list(rgb) + [1.0],
                                                   "metallicFactor": 0.0, "roughnessFactor": roughness}}


def floor_node(half, thick):
    """Mesh 0 as a floor 2 half x 2 half wide whose top is at y = 0."""
    return {"name": "floor", "mesh": 0, "translation": [0.0, -0.5 * thick, 0.0],
            "scale": [2 * half, thick, 2 * half]}


def cube_gltf(scene_name, generator, bin_name, bin_size, vertex_count, index_count, meshes, nodes):
    """A glTF document (text) whose meshes are cube_buffer()'s cube, one per (mesh name, material)
    of `meshes`, placed by `nodes`. One node a line: a thousand nodes stay readable and small."""
    accessors, views, attributes = cube_mesh_layout(vertex_count, index_count)
    doc = {
        "asset": {"version": "2.0", "generator": "lightscatter " + generator},
        "scene": 0,
        "scenes": [{"name": scene_name, "nodes": list(range(len(nodes)))}],
        "nodes": "@NODES@",
        "meshes": [{"name": name, "primitives": [{"attributes": attributes, "indices": 3, "material": k,
                                                  "mode": 4}]} for k, (name, _) in enumerate(meshes)],
        "materials": [m for _, m in meshes],
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"uri": bin_name, "byteLength": bin_size}],
    }
    text = compact(json.dumps(doc, indent=1))
    node_lines = ",\n".join("  " + json.dumps(n, separators=(",", ":")) for n in nodes)
    return text.replace('"@NODES@"', "[\n" + node_lines + "\n ]") + "\n"


def write_scene(out_dir, name, data, gltf_text, scene):
    """OUT_DIR/NAME.bin, .gltf and .json (the SCENE.json `scene`, arrays of numbers on one line)."""
    with open(os.path.join(out_dir, name + ".bin"), "wb") as f:
        f.write(data)
    with open(os.path.join(out_dir, name + ".gltf"), "w") as f:
        f.write(gltf_text)
    write_scene_json(out_dir, name, scene)


def write_scene_json(out_dir, name, scene):
    with open(os.path.join(out_dir, name + ".json"), "w") as f:
        f.write(compact(json.dumps(scene, indent=2)) + "\n")
