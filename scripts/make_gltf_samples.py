#!/usr/bin/env python3
"""Writes assets/gltf/*.gltf and *.glb: small glTF 2.0 files with the structure of public
sample models that real content trips over (scaled nodes, vertex colors, emissive textures,
punctual lights in physical units, cameras, double-sided surfaces). Each is self-contained
(data URIs, or one GLB). Rerun to regenerate: python3 scripts/make_gltf_samples.py"""

import base64, json, math, struct, zlib
from pathlib import Path

OUT = Path(__file__).resolve().parent.parent / "assets" / "gltf"


class Builder:
    def __init__(self):
        self.bin = bytearray()
        self.views, self.accessors = [], []

    def _view(self, data, target=None):
        while len(self.bin) % 4:
            self.bin.append(0)
        view = {"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(data)}
        if target:
            view["target"] = target
        self.bin += data
        self.views.append(view)
        return len(self.views) - 1

    def floats(self, rows, kind, minmax=False):
        data = b"".join(struct.pack("<%df" % len(r), *r) for r in rows)
        acc = {"bufferView": self._view(data, 34962), "componentType": 5126,
               "count": len(rows), "type": kind}
        if minmax:
            acc["min"] = [min(r[k] for r in rows) for k in range(len(rows[0]))]
            acc["max"] = [max(r[k] for r in rows) for k in range(len(rows[0]))]
        self.accessors.append(acc)
        return len(self.accessors) - 1

    def ints(self, rows, kind, component, normalized, minmax=False):
        """An integer vertex attribute (KHR_mesh_quantization): each element padded to 4
        bytes, as glTF asks of vertex attributes, with the bufferView's byteStride saying so."""
        fmt, ctype = {"b": ("b", 5120), "B": ("B", 5121), "h": ("h", 5122), "H": ("H", 5123)}[component]
        size = struct.calcsize("<%d%s" % (len(rows[0]), fmt))
        stride = (size + 3) // 4 * 4
        data = b"".join(struct.pack("<%d%s" % (len(r), fmt), *r) + b"\0" * (stride - size) for r in rows)
        view = self._view(data, 34962)
        self.views[view]["byteStride"] = stride
        acc = {"bufferView": view, "componentType": ctype, "count": len(rows), "type": kind}
        if normalized:
            acc["normalized"] = True
        if minmax:
            acc["min"] = [min(r[k] for r in rows) for k in range(len(rows[0]))]
            acc["max"] = [max(r[k] for r in rows) for k in range(len(rows[0]))]
        self.accessors.append(acc)
        return len(self.accessors) - 1

    def indices(self, idx):
        data = struct.pack("<%dH" % len(idx), *idx)
        self.accessors.append({"bufferView": self._view(data, 34963), "componentType": 5123,
                               "count": len(idx), "type": "SCALAR"})
        return len(self.accessors) - 1

    def primitive(self, mesh, material=None, colors=None):
        pos, nrm, idx = mesh
        p = {"attributes": {"POSITION": self.floats(pos, "VEC3", True),
                            "NORMAL": self.floats(nrm, "VEC3")},
             "indices": self.indices(idx)}
        if colors is not None:
            p["attributes"]["COLOR_0"] = self.floats(colors, "VEC4")
        if material is not None:
            p["material"] = material
        return p

    def document(self, body):
        doc = {"asset": {"version": "2.0", "generator": "ffvk scripts/make_gltf_samples.py"}}
        doc.update(body)
        doc["accessors"] = self.accessors
        doc["bufferViews"] = self.views
        doc["buffers"] = [{"byteLength": len(self.bin)}]
        return doc

    def write_gltf(self, name, body):
        doc = self.document(body)
        doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(bytes(self.bin)).decode()
        (OUT / f"{name}.gltf").write_text(json.dumps(doc, indent=1) + "\n")

    def write_glb(self, name, body):
        js = json.dumps(self.document(body), separators=(",", ":")).encode()
        js += b" " * (-len(js) % 4)
        bn = bytes(self.bin) + b"\0" * (-len(self.bin) % 4)
        total = 12 + 8 + len(js) + 8 + len(bn)
        out = struct.pack("<4sII", b"glTF", 2, total)
        out += struct.pack("<I4s", len(js), b"JSON") + js
        out += struct.pack("<I4s", len(bn), b"BIN\0") + bn
        (OUT / f"{name}.glb").write_bytes(out)


def sphere(radius, slices=32, stacks=16):
    pos, nrm, idx = [], [], []
    for j in range(stacks + 1):
        phi = math.pi * j / stacks
        for i in range(slices + 1):
            th = 2 * math.pi * i / slices
            n = (math.sin(phi) * math.sin(th), math.cos(phi), math.sin(phi) * math.cos(th))
            nrm.append(n)
            pos.append(tuple(radius * c for c in n))
    for j in range(stacks):
        for i in range(slices):
            a, b = j * (slices + 1) + i, (j + 1) * (slices + 1) + i
            idx += [a, b, a + 1, a + 1, b, b + 1]
    return pos, nrm, idx


def cube(h):
    pos, nrm, idx = [], [], []
    for axis in range(3):
        for sign in (1, -1):
            n = [0, 0, 0]; n[axis] = sign
            u = [0, 0, 0]; u[(axis + 1) % 3] = 1
            v = [0, 0, 0]; v[(axis + 2) % 3] = 1
            base = len(pos)
            for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                pos.append(tuple(h * (n[k] + su * u[k] + sv * v[k]) for k in range(3)))
                nrm.append(tuple(n))
            quad = [0, 1, 2, 0, 2, 3] if sign > 0 else [0, 2, 1, 0, 3, 2]
            idx += [base + q for q in quad]
    return pos, nrm, idx


def plane(half, cells=8):
    """A square in the XZ plane facing +Y."""
    pos, nrm, idx = [], [], []
    for j in range(cells + 1):
        for i in range(cells + 1):
            pos.append((-half + 2 * half * i / cells, 0.0, -half + 2 * half * j / cells))
            nrm.append((0.0, 1.0, 0.0))
    for j in range(cells):
        for i in range(cells):
            a, b = j * (cells + 1) + i, (j + 1) * (cells + 1) + i
            idx += [a, b, a + 1, a + 1, b, b + 1]
    return pos, nrm, idx


def half_cylinder(radius, height, segments=24):
    """An open half pipe around +Y, its outside facing away from the axis, open towards +Z."""
    pos, nrm, idx = [], [], []
    for i in range(segments + 1):
        th = math.pi / 2 + math.pi * i / segments  # from +X round through -Z to -X
        n = (math.sin(th), 0.0, math.cos(th))
        for y in (-height / 2, height / 2):
            pos.append((radius * n[0], y, radius * n[2]))
            nrm.append(n)
    for i in range(segments):
        a = 2 * i
        idx += [a, a + 2, a + 1, a + 1, a + 2, a + 3]
    return pos, nrm, idx


def png(width, height, rgba_rows):
    raw = b"".join(b"\0" + bytes(row) for row in rgba_rows)
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw)) + chunk(b"IEND", b""))


def scene_of(nodes):
    return {"scene": 0, "scenes": [{"nodes": nodes}]}


def scaled_node():
    # Like the Duck: geometry in centimetres under a node scaled by 0.01, and a grandchild
    # scaled up again by 100 (a scaled node inside a scaled node).
    b = Builder()
    body = scene_of([0])
    body["nodes"] = [
        {"name": "centimetres", "scale": [0.01, 0.01, 0.01], "mesh": 0, "children": [1]},
        {"name": "metres again", "translation": [150.0, 0.0, 0.0], "scale": [100.0, 100.0, 100.0],
         "children": [2]},
        {"name": "small ball", "scale": [0.5, 0.5, 0.5], "mesh": 1},
    ]
    body["meshes"] = [{"name": "ball", "primitives": [b.primitive(sphere(100.0), 0)]},
                      {"name": "ball 2", "primitives": [b.primitive(sphere(1.0), 1)]}]
    body["materials"] = [
        {"name": "yellow", "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.7, 0.1, 1.0],
                                                    "metallicFactor": 0.0, "roughnessFactor": 0.5}},
        {"name": "blue", "pbrMetallicRoughness": {"baseColorFactor": [0.1, 0.3, 0.8, 1.0],
                                                  "metallicFactor": 0.0, "roughnessFactor": 0.4}}]
    b.write_gltf("scaled_node", body)


def vertex_colors():
    # Like BoxVertexColors: a cube whose faces carry their own COLOR_0, under a grey base color.
    b = Builder()
    mesh = cube(0.5)
    palette = [(1, 0.2, 0.2, 1), (0.2, 1, 1, 1), (0.2, 1, 0.2, 1), (1, 0.2, 1, 1), (0.2, 0.2, 1, 1), (1, 1, 0.2, 1)]
    colors = [palette[v // 4] for v in range(len(mesh[0]))]
    body = scene_of([0])
    body["nodes"] = [{"name": "cube", "rotation": [0.1, 0.3, 0.0, 0.95], "mesh": 0}]
    body["meshes"] = [{"name": "cube", "primitives": [b.primitive(mesh, 0, colors)]}]
    body["materials"] = [{"name": "grey", "pbrMetallicRoughness": {
        "baseColorFactor": [0.8, 0.8, 0.8, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.6}}]
    b.write_gltf("vertex_colors", body)


def emissive():
    # Like the emissive lamps and helmets: emissiveFactor 1 with an emissive texture that is
    # mostly dark, which read as a factor alone would paint the object white.
    b = Builder()
    rows = []
    for y in range(8):
        row = []
        for x in range(8):
            lit = (x + y) % 4 == 0
            row += [255, 140, 40, 255] if lit else [20, 10, 5, 255]
        rows.append(row)
    image = "data:image/png;base64," + base64.b64encode(png(8, 8, rows)).decode()
    body = scene_of([0, 1])
    body["nodes"] = [{"name": "glowing ball", "mesh": 0}, {"name": "plain ball", "translation": [2.2, 0, 0], "mesh": 1}]
    body["meshes"] = [{"name": "glow", "primitives": [b.primitive(sphere(1.0), 0)]},
                      {"name": "plain", "primitives": [b.primitive(sphere(0.6), 1)]}]
    body["materials"] = [
        {"name": "ember", "emissiveFactor": [1.0, 1.0, 1.0], "emissiveTexture": {"index": 0},
         "pbrMetallicRoughness": {"baseColorFactor": [0.3, 0.3, 0.3, 1.0], "metallicFactor": 0.0}},
        {"name": "stone", "pbrMetallicRoughness": {"baseColorFactor": [0.6, 0.6, 0.55, 1.0], "metallicFactor": 0.0}}]
    body["textures"] = [{"source": 0}]
    body["images"] = [{"name": "embers", "uri": image}]
    b.write_gltf("emissive", body)


def lamp():
    # Like LightsPunctualLamp: lights in physical units (a 120 cd bulb, a 60 cd spot, a
    # 2 lux sky), which read as GL colors turn everything white. Written as a GLB.
    b = Builder()
    s = math.sqrt(0.5)
    body = scene_of([0, 1, 2, 3, 4])
    body["extensionsUsed"] = ["KHR_lights_punctual"]
    body["extensions"] = {"KHR_lights_punctual": {"lights": [
        {"name": "bulb", "type": "point", "color": [1.0, 0.9, 0.7], "intensity": 120.0},
        {"name": "spot", "type": "spot", "color": [0.7, 0.8, 1.0], "intensity": 60.0,
         "spot": {"innerConeAngle": 0.3, "outerConeAngle": 0.6}},
        {"name": "sky", "type": "directional", "color": [0.6, 0.7, 1.0], "intensity": 2.0}]}}
    body["nodes"] = [
        {"name": "floor", "mesh": 0},
        {"name": "ball", "translation": [0.0, 0.5, 0.0], "mesh": 1},
        {"name": "bulb", "translation": [-0.8, 1.6, 0.8], "extensions": {"KHR_lights_punctual": {"light": 0}}},
        {"name": "spot", "translation": [1.2, 2.0, 0.0], "rotation": [-s, 0.0, 0.0, s],
         "extensions": {"KHR_lights_punctual": {"light": 1}}},
        {"name": "sky", "rotation": [-0.38, 0.0, 0.0, 0.925], "extensions": {"KHR_lights_punctual": {"light": 2}}},
    ]
    body["meshes"] = [{"name": "floor", "primitives": [b.primitive(plane(2.0), 0)]},
                      {"name": "ball", "primitives": [b.primitive(sphere(0.5), 1)]}]
    body["materials"] = [
        {"name": "floor", "pbrMetallicRoughness": {"baseColorFactor": [0.7, 0.7, 0.7, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.9}},
        {"name": "red", "pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.15, 0.1, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.3}}]
    b.write_glb("lamp", body)


def camera():
    # Like Cameras: the file's own perspective camera (aspect 1.5) off to the side, above.
    b = Builder()
    body = scene_of([0, 1, 2])
    body["nodes"] = [
        {"name": "box", "mesh": 0, "translation": [3.0, 0.0, -2.0]},
        {"name": "ball", "mesh": 1, "translation": [1.5, 0.0, -2.5]},
        # At (3, 2, 4) looking at the box: yaw 0, pitch down by atan(2 / 6).
        {"name": "camera", "camera": 0, "translation": [3.0, 2.0, 4.0], "rotation": [-0.1601822, 0.0, 0.0, 0.9870875]},
    ]
    body["meshes"] = [{"name": "box", "primitives": [b.primitive(cube(0.6), 0)]},
                      {"name": "ball", "primitives": [b.primitive(sphere(0.5), 1)]}]
    body["materials"] = [
        {"name": "green", "pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.7, 0.3, 1.0], "metallicFactor": 0.0}},
        {"name": "white", "pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.9, 0.9, 1.0], "metallicFactor": 0.0}}]
    body["cameras"] = [{"name": "side view", "type": "perspective",
                        "perspective": {"yfov": 0.6, "aspectRatio": 1.5, "znear": 0.1, "zfar": 50.0}}]
    b.write_gltf("camera", body)


def quantized():
    # Like a gltfpack'd model (KHR_mesh_quantization): a ball whose positions are UNSIGNED_SHORT
    # (not normalized) under a node whose uniform scale and translation map them back to
    # metres, normals normalized BYTE, texture coordinates normalized UNSIGNED_SHORT; beside it
    # a box in normalized SHORT positions (its node scales them to its size), normalized SHORT
    # normals and plain BYTE texture coordinates. quantized_plain.gltf is the same model in
    # floats, drawn within the default tolerance of it (a test).
    ball = sphere(0.8)
    box = cube(0.45)
    ball_uv = [(0.5 + math.atan2(p[0], p[2]) / (2 * math.pi), 0.5 - p[1] / 1.6) for p in ball[0]]
    box_uv = [(int(i % 4 in (1, 2)), int(i % 4 in (2, 3))) for i in range(len(box[0]))]
    box_at = (1.6, 0.1, 0.0)
    material = [{"name": "teal", "pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.6, 0.55, 1.0],
                                                          "metallicFactor": 0.0, "roughnessFactor": 0.5}},
                {"name": "amber", "pbrMetallicRoughness": {"baseColorFactor": [0.85, 0.55, 0.15, 1.0],
                                                           "metallicFactor": 0.0, "roughnessFactor": 0.45}}]

    # Quantized.
    b = Builder()
    lo = [min(p[k] for p in ball[0]) for k in range(3)]
    step = max(max(p[k] for p in ball[0]) - lo[k] for k in range(3)) / 65535
    q_pos = [tuple(round((p[k] - lo[k]) / step) for k in range(3)) for p in ball[0]]
    q_nrm = [tuple(round(c * 127) for c in n) for n in ball[1]]
    q_uv = [tuple(round(c * 65535) for c in t) for t in ball_uv]
    ball_prim = {"attributes": {"POSITION": b.ints(q_pos, "VEC3", "H", False, True),
                                "NORMAL": b.ints(q_nrm, "VEC3", "b", True),
                                "TEXCOORD_0": b.ints(q_uv, "VEC2", "H", True)},
                 "indices": b.indices(ball[2]), "material": 0}
    half = 0.45
    s_pos = [tuple(round(c / half * 32767) for c in p) for p in box[0]]
    s_nrm = [tuple(round(c * 32767) for c in n) for n in box[1]]
    box_prim = {"attributes": {"POSITION": b.ints(s_pos, "VEC3", "h", True, True),
                               "NORMAL": b.ints(s_nrm, "VEC3", "h", True),
                               "TEXCOORD_0": b.ints(box_uv, "VEC2", "b", False)},
                "indices": b.indices(box[2]), "material": 1}
    body = scene_of([0, 1])
    body["extensionsUsed"] = ["KHR_mesh_quantization"]
    body["extensionsRequired"] = ["KHR_mesh_quantization"]
    body["nodes"] = [{"name": "ball", "mesh": 0, "translation": lo, "scale": [step] * 3},
                     {"name": "box", "mesh": 1, "translation": list(box_at), "scale": [half] * 3}]
    body["meshes"] = [{"name": "ball", "primitives": [ball_prim]}, {"name": "box", "primitives": [box_prim]}]
    body["materials"] = material
    b.write_gltf("quantized", body)

    # The same in floats.
    b = Builder()
    ball_prim = b.primitive(ball, 0)
    ball_prim["attributes"]["TEXCOORD_0"] = b.floats(ball_uv, "VEC2")
    box_prim = b.primitive(box, 1)
    box_prim["attributes"]["TEXCOORD_0"] = b.floats([tuple(float(c) for c in t) for t in box_uv], "VEC2")
    body = scene_of([0, 1])
    body["nodes"] = [{"name": "ball", "mesh": 0}, {"name": "box", "mesh": 1, "translation": list(box_at)}]
    body["meshes"] = [{"name": "ball", "primitives": [ball_prim]}, {"name": "box", "primitives": [box_prim]}]
    body["materials"] = material
    b.write_gltf("quantized_plain", body)


def double_sided():
    # Like TwoSidedPlane: an open half pipe seen into its hollow, so that its back faces (the
    # inside) show: doubleSided, lit from both sides.
    b = Builder()
    body = scene_of([0])
    body["nodes"] = [{"name": "pipe", "mesh": 0, "rotation": [0.0, 0.3826834, 0.0, 0.9238795]}]
    body["meshes"] = [{"name": "pipe", "primitives": [b.primitive(half_cylinder(1.0, 1.6), 0)]}]
    body["materials"] = [{"name": "sheet", "doubleSided": True, "pbrMetallicRoughness": {
        "baseColorFactor": [0.8, 0.5, 0.3, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.5}}]
    b.write_gltf("double_sided", body)


if __name__ == "__main__":
    OUT.mkdir(parents=True, exist_ok=True)
    for make in (scaled_node, vertex_colors, emissive, lamp, camera, double_sided, quantized):
        make()
    print("wrote", ", ".join(sorted(p.name for p in OUT.iterdir())))
