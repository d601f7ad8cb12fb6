#!/usr/bin/env python3
"""Writes the corpus's glTF models (corpus/gltf/), so they can be remade and reviewed.

- instanced_boxes.gltf (+ .bin): one box mesh placed by two nodes under a rotated group, a second mesh sharing its
  accessors with another material, a ground quad without
  normals (flat normals), a perspective camera, a point light, three metallic-roughness materials;
- orthographic_boxes.gltf: the same boxes, buffer and light through an orthographic camera (xmag 4.5, ymag 3, znear
  0) on a child node of a turned rig;
- textured_quad.glb: a quad with the checker texture embedded in the GLB's binary chunk, nearest filtering, texture
  coordinates tiling it twice; no camera and no light, so raster frames and lights it;
- strip_fan_colors.gltf: a buffer in a data URI; a triangle strip with normalized unsigned-byte RGBA colours, a
  triangle fan with float RGB colours and a BLEND material, a line primitive (skipped); a camera without zfar;
- animated_box.gltf: a box turned by LINEAR rotation keys, moved by CUBICSPLINE translation keys and squashed by STEP
  scale keys; no light, so raster lights it;
- alpha_cutouts.gltf: texture alpha. A leaf-shaped cut-out (MASK, cut-off 0.5, an RGBA texture whose alpha is 0
  outside the leaf, 255 inside and graded across a two-texel rim) swinging on LINEAR rotation keys, a pane whose alpha
  runs from 0.15 to 0.9 across it (BLEND, base colour factor alpha 0.8) in front of it, an opaque back wall and
  floor; images in data URIs, trilinear filtering, a point light and two cameras (the second, "side", square and
  without zfar, for --camera 1); the same model with its buffer and images in files beside it
  (alpha_cutouts_external.gltf, alpha_cutouts.bin, alpha_cutouts_leaf.png, alpha_cutouts_pane.png) and as a GLB
  with the images in its binary chunk (alpha_cutouts.glb), which must render the same bytes.
"""
import base64
import json
import math
import os
import struct
import zlib

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
OUT = os.path.join(ROOT, "corpus", "gltf")
FLOAT, UBYTE, USHORT = 5126, 5121, 5123


class Buffer:
    """One buffer's bytes, each view 4-byte aligned, and the accessors and views that describe them."""

    def __init__(self):
        self.data = b""
        self.views = []
        self.accessors = []

    def view(self, payload):
        self.data += b"\0" * (-len(self.data) % 4)
        self.views.append({"buffer": 0, "byteOffset": len(self.data), "byteLength": len(payload)})
        self.data += payload
        return len(self.views) - 1

    def accessor(self, fmt, values, component, kind, normalized=False, bounds=False):
        per = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4}[kind]
        flat = [c for v in values for c in (v if isinstance(v, (list, tuple)) else [v])]
        entry = {"bufferView": self.view(struct.pack("<%d%s" % (len(flat), fmt), *flat)), "componentType": component,
                 "count": len(flat) // per, "type": kind}
        if normalized:
            entry["normalized"] = True
        if bounds:
            entry["min"] = [min(v[i] for v in values) for i in range(per)]
            entry["max"] = [max(v[i] for v in values) for i in range(per)]
        self.accessors.append(entry)
        return len(self.accessors) - 1


def quaternion(axis, degrees):
    s = math.sin(math.radians(degrees) / 2)
    n = math.sqrt(sum(a * a for a in axis))
    return [axis[0] / n * s, axis[1] / n * s, axis[2] / n * s, math.cos(math.radians(degrees) / 2)]


def box(buffer):
    """A unit cube about the origin: 24 vertices with face normals, 36 unsigned-short indices."""
    positions, normals, indices = [], [], []
    for axis in range(3):
        for sign in (-1, 1):
            n = [0, 0, 0]
            n[axis] = sign
            u, v = [(axis + 1) % 3, (axis + 2) % 3]
            base = len(positions)
            for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                p = [0.0, 0.0, 0.0]
                p[axis], p[u], p[v] = 0.5 * sign, 0.5 * a, 0.5 * b
                positions.append(p)
                normals.append(n)
            quad = [0, 1, 2, 0, 2, 3] if sign > 0 else [0, 2, 1, 0, 3, 2]
            indices += [base + i for i in quad]
    return {"POSITION": buffer.accessor("f", positions, FLOAT, "VEC3", bounds=True),
            "NORMAL": buffer.accessor("f", normals, FLOAT, "VEC3")}, buffer.accessor("H", indices, USHORT, "SCALAR")


def write_glb(name, document, data):
    """A GLB: the 12-byte header, the JSON chunk padded with spaces, the binary chunk (already 4-byte aligned)."""
    text = json.dumps(document).encode()
    text += b" " * (-len(text) % 4)
    chunks = struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(data), 0x004E4942) + data
    with open(os.path.join(OUT, name), "wb") as f:
        f.write(struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks)


def write_json(name, document):
    with open(os.path.join(OUT, name), "w") as f:
        json.dump(document, f, indent=1)
        f.write("\n")


def instanced_boxes(name="instanced_boxes", orthographic=False):
    buffer = Buffer()
    box_attributes, box_indices = box(buffer)
    ground = [[-1, 0, -1], [1, 0, -1], [1, 0, 1], [-1, 0, 1]]
    ground_position = buffer.accessor("f", ground, FLOAT, "VEC3", bounds=True)
    ground_indices = buffer.accessor("B", [0, 2, 1, 0, 3, 2], UBYTE, "SCALAR")
    buffer.data += b"\0" * (-len(buffer.data) % 4)
    with open(os.path.join(OUT, "instanced_boxes.bin"), "wb") as f:
        f.write(buffer.data)
    material = lambda name, colour, metallic, roughness: {
        "name": name, "pbrMetallicRoughness": {"baseColorFactor": colour + [1.0], "metallicFactor": metallic,
                                               "roughnessFactor": roughness}}
    perspective = {"type": "perspective", "perspective": {"yfov": 0.7, "znear": 0.5, "zfar": 50, "aspectRatio": 1.5}}
    # Orthographic: the camera 9 units out on a rig turned 40 degrees about y, pitched 30 degrees down; near at 0.
    ortho = {"type": "orthographic", "orthographic": {"xmag": 4.5, "ymag": 3, "znear": 0, "zfar": 30}}
    camera_node = ({"name": "rig", "rotation": quaternion([0, 1, 0], 40), "children": [7]} if orthographic else
                   {"name": "camera", "camera": 0, "translation": [0, 2.5, 7], "rotation": quaternion([1, 0, 0], -18)})
    extra_nodes = ([{"name": "camera", "camera": 0, "rotation": quaternion([1, 0, 0], -30),
                     "translation": [0, 9 * math.sin(math.radians(30)), 9 * math.cos(math.radians(30))]}]
                   if orthographic else [])
    write_json(name + ".gltf", {
        "asset": {"version": "2.0", "generator": "tools/make_gltf_corpus.py"},
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point", "color": [1, 0.95, 0.9], "intensity": 40}]}},
        "scene": 0,
        "scenes": [{"nodes": [0, 3, 4, 5]}],
        "nodes": [
            {"name": "group", "rotation": quaternion([0, 1, 0], 30), "children": [1, 2, 6]},
            {"name": "box A", "mesh": 0, "translation": [-1.2, 0.4, 0], "scale": [0.8, 0.8, 0.8]},
            {"name": "box B", "mesh": 1, "translation": [1.2, 0.5, 0.2], "rotation": quaternion([1, 1, 0], 45)},
            {"name": "ground", "mesh": 2, "scale": [4, 1, 4]},
            camera_node,
            {"name": "lamp", "translation": [2, 5, 3], "extensions": {"KHR_lights_punctual": {"light": 0}}},
            {"name": "box C", "mesh": 0, "translation": [0, 0.3, -1.5], "scale": [0.6, 0.6, 0.6]},
        ] + extra_nodes,
        "cameras": [ortho if orthographic else perspective],
        "meshes": [
            {"name": "red box", "primitives": [{"attributes": box_attributes, "indices": box_indices, "material": 0}]},
            {"name": "blue box", "primitives": [{"attributes": box_attributes, "indices": box_indices, "material": 1}]},
            {"name": "ground", "primitives": [{"attributes": {"POSITION": ground_position}, "indices": ground_indices,
                                               "material": 2}]},
        ],
        "materials": [material("red", [0.8, 0.15, 0.1], 0.0, 0.4), material("blue", [0.2, 0.3, 0.9], 0.5, 0.3),
                      material("ground", [0.6, 0.6, 0.55], 0.0, 1.0)],
        "buffers": [{"uri": "instanced_boxes.bin", "byteLength": len(buffer.data)}],
        "bufferViews": buffer.views,
        "accessors": buffer.accessors,
    })


def textured_quad():
    buffer = Buffer()
    positions = [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]]
    uvs = [[0, 2], [2, 2], [2, 0], [0, 0]]  # glTF's v runs down the image: (0, 0) is its top left
    attributes = {"POSITION": buffer.accessor("f", positions, FLOAT, "VEC3", bounds=True),
                  "NORMAL": buffer.accessor("f", [[0, 0, 1]] * 4, FLOAT, "VEC3"),
                  "TEXCOORD_0": buffer.accessor("f", uvs, FLOAT, "VEC2")}
    indices = buffer.accessor("H", [0, 1, 2, 0, 2, 3], USHORT, "SCALAR")
    with open(os.path.join(ROOT, "corpus", "textures", "checker.png"), "rb") as f:
        image_view = buffer.view(f.read())
    buffer.data += b"\0" * (-len(buffer.data) % 4)
    document = {
        "asset": {"version": "2.0", "generator": "tools/make_gltf_corpus.py"},
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": attributes, "indices": indices, "material": 0}]}],
        "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}, "metallicFactor": 0}}],
        "textures": [{"sampler": 0, "source": 0}],
        "samplers": [{"magFilter": 9728, "minFilter": 9728, "wrapS": 10497, "wrapT": 10497}],
        "images": [{"bufferView": image_view, "mimeType": "image/png"}],
        "buffers": [{"byteLength": len(buffer.data)}],
        "bufferViews": buffer.views,
        "accessors": buffer.accessors,
    }
    write_glb("textured_quad.glb", document, buffer.data)


def strip_fan_colors():
    buffer = Buffer()
    strip = [[-2 + 0.5 * (i // 2), -0.2 - 0.8 * (i % 2), 0] for i in range(6)]  # counter-clockwise: facing +z
    strip_colours = [[255, 40 * i, 0, 255] for i in range(6)]
    fan = [[1.2, 0, 0.3]] + [[1.2 + math.cos(a), math.sin(a), 0.3] for a in (0, 1.2, 2.4, 3.6)]
    fan_colours = [[1, 1, 1], [0, 1, 0], [0, 0, 1], [1, 1, 0], [0, 1, 1]]
    line = [[-2, 1.5, 0], [2, 1.5, 0]]
    primitives = [
        {"attributes": {"POSITION": buffer.accessor("f", strip, FLOAT, "VEC3", bounds=True),
                        "COLOR_0": buffer.accessor("B", strip_colours, UBYTE, "VEC4", normalized=True)},
         "mode": 5, "material": 0},
        {"attributes": {"POSITION": buffer.accessor("f", fan, FLOAT, "VEC3", bounds=True),
                        "COLOR_0": buffer.accessor("f", fan_colours, FLOAT, "VEC3")},
         "mode": 6, "material": 1},
        {"attributes": {"POSITION": buffer.accessor("f", line, FLOAT, "VEC3", bounds=True)}, "mode": 1},
    ]
    write_json("strip_fan_colors.gltf", {
        "asset": {"version": "2.0", "generator": "tools/make_gltf_corpus.py"},
        "scenes": [{"nodes": [0, 1]}],
        "nodes": [{"mesh": 0}, {"camera": 0, "translation": [0, 0, 6]}],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1}}],
        "meshes": [{"primitives": primitives}],
        "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.8, 1, 1], "metallicFactor": 0}},
                      {"alphaMode": "BLEND", "pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 0.6],
                                                                       "metallicFactor": 0}}],
        "buffers": [{"uri": "data:application/octet-stream;base64," + base64.b64encode(buffer.data).decode(),
                     "byteLength": len(buffer.data)}],
        "bufferViews": buffer.views,
        "accessors": buffer.accessors,
    })


def animated_box():
    buffer = Buffer()
    box_attributes, box_indices = box(buffer)
    times = lambda values: buffer.accessor("f", values, FLOAT, "SCALAR", bounds=False)
    # Rotation: LINEAR keys 150 degrees apart about a tilted axis (x, y, z, w as glTF writes them): under half a
    # turn, so the short way is the way the keys go, and wide enough that normalised lerp would lag slerp by degrees.
    rotation_in = times([0, 1, 2, 3])
    rotation_out = buffer.accessor("f", [quaternion([0.3, 1, 0], a) for a in (0, 150, 300, 450)], FLOAT, "VEC4")
    # Translation: CUBICSPLINE, each key an in-tangent, a value and an out-tangent.
    translation_in = times([0, 1.5, 3])
    translation_out = buffer.accessor("f", [[0, 0, 0], [-1, 0, 0], [0, 2, 0],
                                            [0, 0, 0], [1, 0.5, 0], [0, 0, 0],
                                            [0, -2, 0], [-1, 0, 0], [0, 0, 0]], FLOAT, "VEC3")
    # Scale: STEP, jumping at 2 s.
    scale_in = times([0, 2])
    scale_out = buffer.accessor("f", [[1, 1, 1], [1.3, 0.7, 1.3]], FLOAT, "VEC3")
    write_json("animated_box.gltf", {
        "asset": {"version": "2.0", "generator": "tools/make_gltf_corpus.py"},
        "scenes": [{"nodes": [0, 1]}],
        "nodes": [{"name": "box", "mesh": 0}, {"camera": 0, "translation": [0, 0.8, 5]}],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.5, "zfar": 20}}],
        "meshes": [{"primitives": [{"attributes": box_attributes, "indices": box_indices, "material": 0}]}],
        "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.3, 0.7, 0.4, 1], "metallicFactor": 0,
                                                "roughnessFactor": 0.5}}],
        "animations": [{"name": "tumble", "channels": [
            {"sampler": 0, "target": {"node": 0, "path": "rotation"}},
            {"sampler": 1, "target": {"node": 0, "path": "translation"}},
            {"sampler": 2, "target": {"node": 0, "path": "scale"}}],
            "samplers": [{"input": rotation_in, "output": rotation_out, "interpolation": "LINEAR"},
                         {"input": translation_in, "output": translation_out, "interpolation": "CUBICSPLINE"},
                         {"input": scale_in, "output": scale_out, "interpolation": "STEP"}]}],
        "buffers": [{"uri": "data:application/octet-stream;base64," + base64.b64encode(buffer.data).decode(),
                     "byteLength": len(buffer.data)}],
        "bufferViews": buffer.views,
        "accessors": buffer.accessors,
    })


def png_rgba(width, height, texel):
    """An 8-bit RGBA PNG whose texel (x, y) (row 0 the top) is texel(x, y), a 4-tuple of 0..255."""
    rows = b"".join(b"\0" + bytes(c for x in range(width) for c in texel(x, y)) for y in range(height))
    chunk = lambda kind, data: (struct.pack(">I", len(data)) + kind + data +
                                struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))


def leaf_texel(x, y, size=64):
    """A leaf: inside |u|^1.5 + |v|^1.5 < 1 about the texture's middle, a rim two texels wide graded in alpha; a vein."""
    u, v = (x + 0.5) / size * 2 - 1, (y + 0.5) / size * 2 - 1
    lean = (u - 0.25 * v) * 1.6
    inside = 1 - (abs(lean) ** 1.5 + abs(v * 1.05) ** 1.5)
    alpha = max(0, min(255, round(255 * inside * size / 4)))
    vein = abs(lean) < 0.06
    return (150 if vein else 40 + x, 90 if vein else 120 + y, 30, alpha)


def pane_texel(x, y, size=32):
    """Alpha from 0.15 at the left to 0.9 at the right; blue, with a lighter stripe every 8 rows."""
    alpha = round(255 * (0.15 + 0.75 * x / (size - 1)))
    light = (y // 4) % 2 == 0
    return (90 if light else 40, 140 if light else 90, 230, alpha)


def alpha_cutouts():
    buffer = Buffer()
    quad = lambda w, h: buffer.accessor("f", [[-w, -h, 0], [w, -h, 0], [w, h, 0], [-w, h, 0]], FLOAT, "VEC3", bounds=True)
    normal = buffer.accessor("f", [[0, 0, 1]] * 4, FLOAT, "VEC3")
    uv = buffer.accessor("f", [[0, 1], [1, 1], [1, 0], [0, 0]], FLOAT, "VEC2")  # glTF's v runs down the image
    indices = buffer.accessor("B", [0, 1, 2, 0, 2, 3], UBYTE, "SCALAR")
    leaf_quad, pane_quad, wall_quad = quad(1, 1), quad(0.9, 0.7), quad(3, 2)
    box_attributes, box_indices = box(buffer)
    swing_in = buffer.accessor("f", [0, 1, 2], FLOAT, "SCALAR")
    swing_out = buffer.accessor("f", [quaternion([0, 1, 0], a) for a in (-35, 10, 40)], FLOAT, "VEC4")
    image = lambda png: {"uri": "data:image/png;base64," + base64.b64encode(png).decode()}
    material = lambda name, colour, **more: dict({"name": name, "pbrMetallicRoughness": dict(
        {"baseColorFactor": colour, "metallicFactor": 0, "roughnessFactor": 0.6}, **more.pop("pbr", {}))}, **more)
    primitive = lambda attributes, mat: {"primitives": [{"attributes": attributes, "indices": indices, "material": mat}]}
    pngs = [png_rgba(64, 64, leaf_texel), png_rgba(32, 32, pane_texel)]
    document = {
        "asset": {"version": "2.0", "generator": "tools/make_gltf_corpus.py"},
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": [{"type": "point", "color": [1, 1, 0.95], "intensity": 30}]}},
        "scenes": [{"nodes": [0, 1, 2, 3, 4, 5, 6]}],
        "nodes": [
            {"name": "leaf", "mesh": 0, "translation": [-0.4, 0.2, 0.3], "rotation": quaternion([0, 1, 0], -35)},
            {"name": "pane", "mesh": 1, "translation": [0.6, 0.1, 1.2]},
            {"name": "wall", "mesh": 2, "translation": [0, 0.5, -1.5]},
            {"name": "floor", "mesh": 3, "translation": [0, -1.3, 0], "scale": [6, 0.2, 4]},
            {"name": "camera", "camera": 0, "translation": [0.3, 0.6, 5.5], "rotation": quaternion([1, 0, 0], -6)},
            {"name": "lamp", "translation": [1.5, 3, 4], "extensions": {"KHR_lights_punctual": {"light": 0}}},
            {"name": "side", "camera": 1, "translation": [-4.5, 1.2, 3.5], "rotation": quaternion([0, 1, 0], -50)},
        ],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.75, "znear": 0.5, "zfar": 30, "aspectRatio": 1.5}},
                    {"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.3, "aspectRatio": 1.0}}],
        "meshes": [
            primitive({"POSITION": leaf_quad, "NORMAL": normal, "TEXCOORD_0": uv}, 0),
            primitive({"POSITION": pane_quad, "NORMAL": normal, "TEXCOORD_0": uv}, 1),
            primitive({"POSITION": wall_quad, "NORMAL": normal}, 2),
            {"primitives": [{"attributes": box_attributes, "indices": box_indices, "material": 3}]},
        ],
        "materials": [
            material("leaf", [1, 1, 1, 1], pbr={"baseColorTexture": {"index": 0}}, alphaMode="MASK", alphaCutoff=0.5),
            material("pane", [1, 1, 1, 0.8], pbr={"baseColorTexture": {"index": 1}}, alphaMode="BLEND"),
            material("wall", [0.75, 0.7, 0.6, 1]),
            material("floor", [0.45, 0.5, 0.45, 1]),
        ],
        "textures": [{"source": 0}, {"source": 1}],
        "images": [image(png) for png in pngs],
        "animations": [{"name": "swing", "channels": [{"sampler": 0, "target": {"node": 0, "path": "rotation"}}],
                        "samplers": [{"input": swing_in, "output": swing_out, "interpolation": "LINEAR"}]}],
        "buffers": [{"uri": "data:application/octet-stream;base64," + base64.b64encode(buffer.data).decode(),
                     "byteLength": len(buffer.data)}],
        "bufferViews": buffer.views,
        "accessors": buffer.accessors,
    }
    write_json("alpha_cutouts.gltf", document)
    # The same model with its buffer and images in files of their own beside it.
    external = dict(document, buffers=[{"uri": "alpha_cutouts.bin", "byteLength": len(buffer.data)}],
                    images=[{"uri": "alpha_cutouts_%s.png" % name} for name in ("leaf", "pane")])
    write_json("alpha_cutouts_external.gltf", external)
    with open(os.path.join(OUT, "alpha_cutouts.bin"), "wb") as f:
        f.write(buffer.data)
    for name, png in zip(("leaf", "pane"), pngs):
        with open(os.path.join(OUT, "alpha_cutouts_%s.png" % name), "wb") as f:
            f.write(png)
    # And as a GLB: the images in buffer views of the binary chunk, the one buffer without a uri.
    views = [dict(v) for v in buffer.views]
    data = buffer.data
    images = []
    for png in pngs:
        data += b"\0" * (-len(data) % 4)
        views.append({"buffer": 0, "byteOffset": len(data), "byteLength": len(png)})
        images.append({"bufferView": len(views) - 1, "mimeType": "image/png"})
        data += png
    data += b"\0" * (-len(data) % 4)
    write_glb("alpha_cutouts.glb", dict(document, buffers=[{"byteLength": len(data)}], bufferViews=views, images=images),
              data)


if __name__ == "__main__":
    os.makedirs(OUT, exist_ok=True)
    instanced_boxes()
    instanced_boxes("orthographic_boxes", orthographic=True)
    textured_quad()
    strip_fan_colors()
    animated_box()
    alpha_cutouts()
