#!/usr/bin/python3
"""Writes the garden glTF scene: assets/scenes/garden/garden.gltf, garden.bin and its PNGs.

Usage: tools/make_garden_gltf.py [OUT_DIR]   (default: assets/scenes/garden; Python 3 only)

A courtyard corner that shows what ispm reads from glTF: a ground of stone tiles (base colour
texture), a brick wall whose bricks stand out of their mortar by a normal map (normalTexture,
with TANGENT), a smooth sphere (NORMAL) and a small tree of alpha-tested leaf cards (alphaMode
MASK, doubleSided) on a trunk. Lights and the camera are in assets/scenes/garden.json. The
textures are drawn here procedurally and written as PNG with zlib, so the output is the same
on every run.
"""
import json
import math
import os
import random
import struct
import sys
import zlib

WALL_HALF_WIDTH_M = 4.0  # wider than the view: the wall hides the horizon
WALL_HEIGHT_M = 2.4
WALL_Z_M = 2.0  # the wall's front face, facing -z (toward the camera)
WALL_THICKNESS_M = 0.3
BRICK_TILE_M = 2.0  # the brick texture repeats every 2 m along both axes
GROUND_HALF_M = 8.0
GROUND_TILE_M = 1.0  # one stone tile per texture repeat
SPHERE_CENTRE = (-1.3, 0.55, 0.3)
SPHERE_RADIUS_M = 0.55
SPHERE_SEGMENTS = 40
SPHERE_RINGS = 20
TREE_BASE = (1.3, 0.0, 1.0)
TRUNK_HALF_M = 0.06
TRUNK_HEIGHT_M = 1.3
CROWN_CENTRE = (1.3, 1.6, 1.0)
CROWN_RADIUS_M = 0.6
LEAF_CARDS = 40
LEAF_CARD_HALF_M = 0.22
SEED = 7

BRICK_PX = 128  # brick texture side (both the colour and the normal map)
BRICK_ROWS = 8  # courses per texture: 25 cm each over BRICK_TILE_M
BRICKS_PER_ROW = 4
MORTAR_PX = 2
BEVEL_PX = 2  # the brick's edge rounds off over this many texels
NORMAL_STRENGTH = 1.5  # height of a brick face above the mortar, in texels, per texel of bevel
GROUND_PX = 64
LEAF_PX = 64


# ---------------------------------------------------------------------------------------------
# PNG


def write_png(path, width, height, rgba):
    """RGBA 8-bit, rows top to bottom; `rgba` a flat list of width * height * 4 ints."""
    raw = bytearray()
    for y in range(height):
        raw.append(0)  # filter: none
        raw.extend(bytes(rgba[4 * width * y: 4 * width * (y + 1)]))

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body))

    header = struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", header))
        f.write(chunk(b"IDAT", zlib.compress(bytes(raw), 9)))
        f.write(chunk(b"IEND", b""))


def to_byte(x):
    return max(0, min(255, int(round(x * 255.0))))


# ---------------------------------------------------------------------------------------------
# Textures


def brick_height(x, y):
    """Height of the brick pattern at texel (x, y), 0 in the mortar, 1 on a brick's face: bricks
    in running bond, their edges bevelled. Wraps at the texture's edges."""
    course_px = BRICK_PX // BRICK_ROWS
    brick_px = BRICK_PX // BRICKS_PER_ROW
    x %= BRICK_PX
    y %= BRICK_PX
    row = y // course_px
    shift = (brick_px // 2) * (row % 2)
    bx = (x + shift) % brick_px
    by = y % course_px
    # Distance (in texels) to the nearest mortar line, counted from the brick's side.
    edge = min(bx, brick_px - 1 - bx, by, course_px - 1 - by) - MORTAR_PX + 1
    if edge <= 0:
        return 0.0
    return min(1.0, edge / BEVEL_PX)


def brick_id(x, y):
    course_px = BRICK_PX // BRICK_ROWS
    brick_px = BRICK_PX // BRICKS_PER_ROW
    row = (y % BRICK_PX) // course_px
    shift = (brick_px // 2) * (row % 2)
    return row * BRICKS_PER_ROW + ((x % BRICK_PX) + shift) // brick_px % BRICKS_PER_ROW


def make_brick_textures():
    rng = random.Random(SEED)
    shades = [rng.uniform(0.8, 1.1) for _ in range(BRICK_ROWS * BRICKS_PER_ROW)]
    albedo = []
    normal = []
    for y in range(BRICK_PX):
        for x in range(BRICK_PX):
            h = brick_height(x, y)
            if h > 0.0:
                s = shades[brick_id(x, y)] * rng.uniform(0.93, 1.0)
                colour = (0.62 * s, 0.27 * s, 0.18 * s)  # sRGB
            else:
                g = rng.uniform(0.68, 0.75)
                colour = (g, g * 0.97, g * 0.92)
            albedo += [to_byte(c) for c in colour] + [255]
            # Tangent space: +x along u (right), +y up the image (-v, the row above). The
            # normal of a height field h is (-dh/dx, -dh/dy_up, 1), and dh/dy_up = -dh/drow.
            dx = (brick_height(x + 1, y) - brick_height(x - 1, y)) * 0.5
            drow = (brick_height(x, y + 1) - brick_height(x, y - 1)) * 0.5
            n = (-NORMAL_STRENGTH * dx, NORMAL_STRENGTH * drow, 1.0)
            length = math.sqrt(sum(c * c for c in n))
            normal += [to_byte(0.5 * (c / length + 1.0)) for c in n] + [255]
    return albedo, normal


def make_ground_texture():
    """Square stone tiles with grey joints, sRGB."""
    rng = random.Random(SEED + 1)
    tile = rng.uniform(0.9, 1.05)
    out = []
    for y in range(GROUND_PX):
        for x in range(GROUND_PX):
            joint = x < 2 or y < 2
            if joint:
                c = (0.42, 0.42, 0.40)
            else:
                s = tile * rng.uniform(0.94, 1.0)
                c = (0.66 * s, 0.62 * s, 0.55 * s)
            out += [to_byte(v) for v in c] + [255]
    return out


def make_leaf_texture():
    """Three leaves on a transparent card: each a pointed ellipse (alpha 1 inside, 0 outside)
    with a lighter midrib, sRGB green."""
    leaves = [  # centre (u, v), half length, half width, angle (radians)
        (0.50, 0.50, 0.42, 0.17, 0.5),
        (0.28, 0.30, 0.22, 0.09, -0.9),
        (0.72, 0.72, 0.22, 0.09, 2.3),
    ]
    out = []
    for y in range(LEAF_PX):
        for x in range(LEAF_PX):
            u = (x + 0.5) / LEAF_PX
            v = (y + 0.5) / LEAF_PX
            rgba = [0, 0, 0, 0]
            for cu, cv, a, b, angle in leaves:
                du, dv = u - cu, v - cv
                s = du * math.cos(angle) + dv * math.sin(angle)
                t = -du * math.sin(angle) + dv * math.cos(angle)
                if abs(s) >= a:
                    continue
                # Narrowing toward both tips: a lens rather than an ellipse.
                width = b * (1.0 - (s / a) ** 2) ** 0.7
                if abs(t) < width:
                    rib = abs(t) < 0.012
                    shade = 0.85 + 0.15 * (s / a)
                    colour = (0.45, 0.62, 0.25) if rib else (0.24 * shade, 0.48 * shade, 0.16)
                    rgba = [to_byte(c) for c in colour] + [255]
            out += rgba
    return out


# ---------------------------------------------------------------------------------------------
# Geometry


class Mesh:
    """One primitive's vertex streams and triangles."""

    def __init__(self):
        self.positions = []
        self.normals = []
        self.texcoords = []
        self.tangents = []
        self.indices = []

    def add_quad(self, corners, uvs, normal, tangent=None):
        """Corners counter-clockwise seen from the side `normal` faces."""
        base = len(self.positions)
        for p, uv in zip(corners, uvs):
            self.positions.append(p)
            self.normals.append(normal)
            self.texcoords.append(uv)
            if tangent is not None:
                self.tangents.append(tangent)
        self.indices += [base, base + 1, base + 2, base, base + 2, base + 3]


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def normalise(a):
    length = math.sqrt(dot(a, a))
    return tuple(x / length for x in a)


def add_box(mesh, lo, hi, tile_m, with_tangents):
    """An axis-aligned box's six faces, each with texture coordinates in metres / tile_m: u to
    the right and v down as one looks at the face from outside (the top and bottom: u along +x,
    v along +z). Tangents (glTF TANGENT) are +u with handedness +1 for every face."""
    faces = [
        ((0, 0, -1), (-1, 0, 0)), ((0, 0, 1), (1, 0, 0)),
        ((-1, 0, 0), (0, 0, 1)), ((1, 0, 0), (0, 0, -1)),
        ((0, 1, 0), (1, 0, 0)), ((0, -1, 0), (1, 0, 0)),
    ]
    centre = tuple(0.5 * (a + b) for a, b in zip(lo, hi))
    half = tuple(0.5 * (b - a) for a, b in zip(lo, hi))
    for n, right in faces:
        # The image's up on the face: n x right, so that (right, up, n) is right-handed and the
        # handedness is +1 (glTF: bitangent = w cross(n, t), up the image).
        up = cross(n, right)
        face_centre = tuple(c + h * k for c, h, k in zip(centre, half, n))
        half_right = abs(dot(half, right))
        half_up = abs(dot(half, up))
        corners = []
        uvs = []
        for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):  # counter-clockwise from outside
            p = tuple(c + su * half_right * r + sv * half_up * u
                      for c, r, u in zip(face_centre, right, up))
            corners.append(p)
            # u: metres along `right`; v: metres down (-up), both from the world's origin, so
            # neighbouring faces and boxes continue the pattern.
            uvs.append((dot(p, right) / tile_m, -dot(p, up) / tile_m))
        tangent = (right[0], right[1], right[2], 1.0) if with_tangents else None
        mesh.add_quad(corners, uvs, n, tangent)


def make_sphere(mesh):
    cx, cy, cz = SPHERE_CENTRE
    for r in range(SPHERE_RINGS + 1):
        theta = math.pi * r / SPHERE_RINGS
        pole = r in (0, SPHERE_RINGS)
        sin_theta = 0.0 if pole else math.sin(theta)
        for s in range(SPHERE_SEGMENTS + 1):
            phi = 2.0 * math.pi * (s % SPHERE_SEGMENTS) / SPHERE_SEGMENTS
            n = (sin_theta * math.cos(phi), math.cos(theta), -sin_theta * math.sin(phi))
            mesh.positions.append((cx + SPHERE_RADIUS_M * n[0], cy + SPHERE_RADIUS_M * n[1],
                                   cz + SPHERE_RADIUS_M * n[2]))
            mesh.normals.append(n)
            mesh.texcoords.append((s / SPHERE_SEGMENTS, r / SPHERE_RINGS))

    def at(r, s):
        return r * (SPHERE_SEGMENTS + 1) + s

    for r in range(SPHERE_RINGS):
        for s in range(SPHERE_SEGMENTS):
            if r > 0:
                mesh.indices += [at(r, s), at(r + 1, s), at(r, s + 1)]
            if r + 1 < SPHERE_RINGS:
                mesh.indices += [at(r, s + 1), at(r + 1, s), at(r + 1, s + 1)]


def make_leaves(mesh):
    """Square cards scattered in a ball round the crown's centre, each turned at random."""
    rng = random.Random(SEED + 2)
    for _ in range(LEAF_CARDS):
        while True:
            offset = tuple(rng.uniform(-1.0, 1.0) for _ in range(3))
            if dot(offset, offset) <= 1.0:
                break
        centre = tuple(c + CROWN_RADIUS_M * o for c, o in zip(CROWN_CENTRE, offset))
        n = normalise(tuple(rng.gauss(0.0, 1.0) for _ in range(3)))
        helper = (0.0, 1.0, 0.0) if abs(n[1]) < 0.9 else (1.0, 0.0, 0.0)
        right = normalise(cross(helper, n))
        up = cross(n, right)
        h = LEAF_CARD_HALF_M
        corners = [tuple(c + h * (su * r + sv * u) for c, r, u in zip(centre, right, up))
                   for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
        mesh.add_quad(corners, [(0, 1), (1, 1), (1, 0), (0, 0)], n)


# ---------------------------------------------------------------------------------------------
# glTF


class Writer:
    """Accumulates the binary buffer and the JSON's views and accessors."""

    def __init__(self):
        self.data = bytearray()
        self.views = []
        self.accessors = []

    def add(self, values, fmt, count, kind, component, target, bounds=False):
        while len(self.data) % 4:
            self.data.append(0)
        offset = len(self.data)
        self.data.extend(struct.pack("<" + fmt * len(values), *values))
        self.views.append({"buffer": 0, "byteOffset": offset,
                           "byteLength": len(self.data) - offset, "target": target})
        accessor = {"bufferView": len(self.views) - 1, "componentType": component,
                    "count": count, "type": kind}
        if bounds:
            width = len(values) // count
            accessor["min"] = [min(values[i::width]) for i in range(width)]
            accessor["max"] = [max(values[i::width]) for i in range(width)]
        self.accessors.append(accessor)
        return len(self.accessors) - 1

    def add_mesh(self, mesh, material, name):
        array_buffer, element_buffer = 34962, 34963
        float_type, uint_type = 5126, 5125
        flat = [c for p in mesh.positions for c in p]
        count = len(mesh.positions)
        attributes = {
            "POSITION": self.add(flat, "f", count, "VEC3", float_type, array_buffer, True),
            "NORMAL": self.add([c for n in mesh.normals for c in n], "f", count, "VEC3",
                               float_type, array_buffer),
            "TEXCOORD_0": self.add([c for t in mesh.texcoords for c in t], "f", count, "VEC2",
                                   float_type, array_buffer),
        }
        if mesh.tangents:
            attributes["TANGENT"] = self.add([c for t in mesh.tangents for c in t], "f", count,
                                             "VEC4", float_type, array_buffer)
        indices = self.add(mesh.indices, "I", len(mesh.indices), "SCALAR", uint_type,
                           element_buffer)
        return {"name": name, "primitives": [{"attributes": attributes, "indices": indices,
                                              "material": material, "mode": 4}]}


def main():
    out_dir = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "..", "assets", "scenes", "garden")
    os.makedirs(out_dir, exist_ok=True)

    brick_albedo, brick_normal = make_brick_textures()
    write_png(os.path.join(out_dir, "brick_albedo.png"), BRICK_PX, BRICK_PX, brick_albedo)
    write_png(os.path.join(out_dir, "brick_normal.png"), BRICK_PX, BRICK_PX, brick_normal)
    write_png(os.path.join(out_dir, "ground.png"), GROUND_PX, GROUND_PX, make_ground_texture())
    write_png(os.path.join(out_dir, "leaf.png"), LEAF_PX, LEAF_PX, make_leaf_texture())

    ground = Mesh()
    g = GROUND_HALF_M
    ground.add_quad([(-g, 0, -g), (-g, 0, g), (g, 0, g), (g, 0, -g)],
                    [(-g / GROUND_TILE_M, -g / GROUND_TILE_M), (-g / GROUND_TILE_M, g / GROUND_TILE_M),
                     (g / GROUND_TILE_M, g / GROUND_TILE_M), (g / GROUND_TILE_M, -g / GROUND_TILE_M)],
                    (0, 1, 0))
    wall = Mesh()
    add_box(wall, (-WALL_HALF_WIDTH_M, 0.0, WALL_Z_M),
            (WALL_HALF_WIDTH_M, WALL_HEIGHT_M, WALL_Z_M + WALL_THICKNESS_M), BRICK_TILE_M, True)
    sphere = Mesh()
    make_sphere(sphere)
    trunk = Mesh()
    x, y, z = TREE_BASE
    add_box(trunk, (x - TRUNK_HALF_M, y, z - TRUNK_HALF_M),
            (x + TRUNK_HALF_M, y + TRUNK_HEIGHT_M, z + TRUNK_HALF_M), 1.0, False)
    leaves = Mesh()
    make_leaves(leaves)

    writer = Writer()
    meshes = [writer.add_mesh(ground, 0, "ground"), writer.add_mesh(wall, 1, "brick_wall"),
              writer.add_mesh(sphere, 2, "sphere"), writer.add_mesh(trunk, 3, "trunk"),
              writer.add_mesh(leaves, 4, "leaves")]

    def material(name, base, roughness, texture=None, **extra):
        pbr = {"baseColorFactor": list(base) + [1.0], "metallicFactor": 0.0,
               "roughnessFactor": roughness}
        if texture is not None:
            pbr["baseColorTexture"] = {"index": texture}
        m = {"name": name, "pbrMetallicRoughness": pbr}
        m.update(extra)
        return m

    document = {
        "asset": {"version": "2.0", "generator": "ispm tools/make_garden_gltf.py"},
        "scene": 0,
        "scenes": [{"name": "garden", "nodes": list(range(len(meshes)))}],
        "nodes": [{"name": m["name"], "mesh": i} for i, m in enumerate(meshes)],
        "meshes": meshes,
        "materials": [
            material("stone_tiles", (1, 1, 1), 1.0, 0),
            material("brick", (1, 1, 1), 0.9, 1, normalTexture={"index": 2, "scale": 1.0}),
            material("sphere", (0.8, 0.8, 0.76), 1.0),
            material("bark", (0.33, 0.24, 0.16), 1.0),
            material("leaf", (1, 1, 1), 1.0, 3, alphaMode="MASK", alphaCutoff=0.5,
                     doubleSided=True),
        ],
        "textures": [{"source": i} for i in range(4)],
        "images": [{"uri": "ground.png"}, {"uri": "brick_albedo.png"},
                   {"uri": "brick_normal.png"}, {"uri": "leaf.png"}],
        "buffers": [{"uri": "garden.bin", "byteLength": len(writer.data)}],
        "bufferViews": writer.views,
        "accessors": writer.accessors,
    }
    with open(os.path.join(out_dir, "garden.bin"), "wb") as f:
        f.write(writer.data)
    with open(os.path.join(out_dir, "garden.gltf"), "w") as f:
        json.dump(document, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
