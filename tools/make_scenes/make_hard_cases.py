#!/usr/bin/python3
"""Writes scenes/hard/: one SCENE.json per hard case of docs/model.md, over a small open scene (ground,
a grille of bars, a box) in hard_cases.gltf, a city of boxes 20 km deep in hard_city.gltf, or
(point_in_cage) a small cage of bars on the ground in hard_cage.gltf. Lights placed at screen
positions use the same camera and Vulkan projection as the host, for the suite's 16:9 screens.
Standard library only.

    /usr/bin/python3 tools/make_scenes/make_hard_cases.py scenes/hard
"""
import base64
import json
import math
import struct
import sys
from pathlib import Path

EYE = (0.0, 2.5, 9.0)
TARGET = (0.0, 1.5, 0.0)
FOV = 60.0
ASPECT = 16.0 / 9.0
SUITE = (64, 36)  # the hard-case tests' screen; pixel-exact cases are placed for it


def sub(a, b): return tuple(x - y for x, y in zip(a, b))
def add(a, b): return tuple(x + y for x, y in zip(a, b))
def mul(a, s): return tuple(x * s for x in a)
def dot(a, b): return sum(x * y for x, y in zip(a, b))
def cross(a, b): return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
def norm(a): return mul(a, 1.0 / math.sqrt(dot(a, a)))


FORWARD = norm(sub(TARGET, EYE))
RIGHT = norm(cross(FORWARD, (0.0, 1.0, 0.0)))
UP = cross(RIGHT, FORWARD)


def through_ndc(x, y, distance):
    """World point at `distance` along the ray through NDC (x, y): Vulkan clip, y down."""
    t = math.tan(math.radians(FOV) / 2)
    d = norm(add(add(FORWARD, mul(RIGHT, x * t * ASPECT)), mul(UP, -y * t)))
    return add(EYE, mul(d, distance))


def box(center, half):
    """Triangles of an axis-aligned box, outward counter-clockwise."""
    cx, cy, cz = center
    hx, hy, hz = half
    faces = []
    for axis in range(3):
        for sign in (-1, 1):
            n = [0, 0, 0]
            n[axis] = sign
            u = [0, 0, 0]
            v = [0, 0, 0]
            u[(axis + 1) % 3] = 1
            v[(axis + 2) % 3] = 1
            if sign < 0:
                u, v = v, u
            corner = [cx, cy, cz]
            corner[axis] += sign * half[axis]
            sizes = half
            quad = []
            for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
                p = list(corner)
                for k in range(3):
                    p[k] += a * u[k] * sizes[k] + b * v[k] * sizes[k]
                quad.append((tuple(p), tuple(n)))
            faces.append(quad)
    return faces


GROUND = [[((-15, 0, -15), (0, 1, 0)), ((-15, 0, 15), (0, 1, 0)), ((15, 0, 15), (0, 1, 0)), ((15, 0, -15), (0, 1, 0))]]


def open_scene_quads():
    """The ground, a grille of five bars and a box: hard_cases.gltf."""
    quads = list(GROUND)
    for i in range(-2, 3):
        quads += box((0.5 * i, 3.0, 0.0), (0.08, 0.05, 1.6))
    quads += box((-1.2, 1.0, 0.4), (0.5, 1.0, 0.1))
    return quads


CITY_ROWS, CITY_COLUMNS = 24, 6  # blocks along the view (-z), and across it


def city_quads():
    """Ground 2 km wide and 21 km deep, and towers 10 to 150 m tall on a grid of blocks 800 m deep
    and 300 m wide either side of an avenue along -z; heights from a fixed linear congruential
    sequence."""
    quads = [[((-1000, 0, -20500), (0, 1, 0)), ((-1000, 0, 500), (0, 1, 0)), ((1000, 0, 500), (0, 1, 0)),
              ((1000, 0, -20500), (0, 1, 0))]]
    state = 12345
    for row in range(CITY_ROWS):
        for column in range(CITY_COLUMNS):
            state = (1103515245 * state + 12345) % 2**31
            height = 10.0 + 140.0 * (state / 2**31) ** 2
            x = (column - (CITY_COLUMNS - 1) / 2) * 300.0
            x += 60.0 if x > 0 else -60.0  # the avenue
            z = -400.0 - 800.0 * row
            quads += box((x, height / 2, z), (90.0, height / 2, 250.0))
    return quads


# A small cage of bars around a point light (hard_cage.gltf): bars on all six sides, so the cube
# map's six faces all carry shadows, and from outside the cage the bars frame the light's glow.
CAGE_CENTER = (0.0, 1.2, 0.0)
CAGE_HALF = 0.3    # half the cage's size, metres
CAGE_BAR = 0.02    # half a bar's thickness
CAGE_STEPS = (-0.15, 0.0, 0.15)  # inner bars along a side
# The light hangs off the cage's centre, so that the camera, 2.7 m out and 3 degrees up on the line
# from the back wall's middle bar through the light, sees the light through a gap of the front wall
# with that bar right behind it.
CAGE_LIGHT = (0.07, 1.26, 0.05)


def cage_camera(distance=2.7, elevation=3.0):
    back_bar = (CAGE_CENTER[0], CAGE_LIGHT[1], CAGE_CENTER[2] - CAGE_HALF)
    across = norm((CAGE_LIGHT[0] - back_bar[0], 0.0, CAGE_LIGHT[2] - back_bar[2]))
    e = math.radians(elevation)
    direction = add(mul(across, math.cos(e)), (0.0, math.sin(e), 0.0))
    return {"position": [round(x, 4) for x in add(CAGE_LIGHT, mul(direction, distance))],
            "target": [round(x, 4) for x in add(CAGE_LIGHT, (0.05, -0.1, 0.0))]}


def cage_bars():
    """(centre, half size) of every bar of the cage, as tools/make_scenes/make_point_cage.py builds its cage."""
    lx, ly, lz = CAGE_CENTER
    h, b = CAGE_HALF, CAGE_BAR
    bars = []
    posts = set()
    for s in (-h, h):
        for t in (-h,) + CAGE_STEPS + (h,):
            posts.add((t, s))
            posts.add((s, t))
    for (x, z) in sorted(posts):
        bars.append(((lx + x, ly, lz + z), (b, h + b, b)))
    for y in (-h, h):
        for z in CAGE_STEPS:
            bars.append(((lx, ly + y, lz + z), (h, b, b)))
        for x in (-h, h):
            bars.append(((lx + x, ly + y, lz), (b, b, h)))
        for z in (-h, h):
            bars.append(((lx, ly + y, lz + z), (h, b, b)))
    return bars


def cage_quads():
    """The ground and the cage's bars."""
    quads = list(GROUND)
    for centre, half in cage_bars():
        quads += box(centre, half)
    return quads


def write_gltf(path, quads):
    positions, normals, indices = [], [], []
    for q in quads:
        base = len(positions)
        for p, n in q:
            positions.append(p)
            normals.append(n)
        indices += [base, base + 1, base + 2, base, base + 2, base + 3]
    pos = b"".join(struct.pack("<3f", *p) for p in positions)
    nrm = b"".join(struct.pack("<3f", *n) for n in normals)
    idx = b"".join(struct.pack("<I", i) for i in indices)
    blob = pos + nrm + idx
    lo = [min(p[k] for p in positions) for k in range(3)]
    hi = [max(p[k] for p in positions) for k in range(3)]
    gltf = {
        "asset": {"version": "2.0", "generator": "tools/make_hard_cases.py"},
        "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2, "material": 0}]}],
        "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.7, 0.68, 0.64, 1.0]}}],
        "buffers": [{"byteLength": len(blob), "uri": "data:application/octet-stream;base64," +
                     base64.b64encode(blob).decode()}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": len(pos), "target": 34962},
                        {"buffer": 0, "byteOffset": len(pos), "byteLength": len(nrm), "target": 34962},
                        {"buffer": 0, "byteOffset": len(pos) + len(nrm), "byteLength": len(idx), "target": 34963}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": len(positions), "type": "VEC3",
                       "min": lo, "max": hi},
                      {"bufferView": 1, "componentType": 5126, "count": len(normals), "type": "VEC3"},
                      {"bufferView": 2, "componentType": 5125, "count": len(indices), "type": "SCALAR"}],
    }
    path.write_text(json.dumps(gltf))


def spot(position, direction, half=30.0, intensity=(400.0, 380.0, 350.0)):
    return {"type": "spot", "position": list(position), "direction": list(direction), "intensity": list(intensity),
            "halfAngleDegrees": half, "range": 30.0, "radius": 0.05, "shadowMapSize": 512}


def soft_spot(position, direction, inner, outer):
    """A spot as KHR_lights_punctual gives it: full intensity within `inner` degrees of its axis,
    falling smoothly to nothing at `outer`."""
    s = spot(position, direction)
    del s["halfAngleDegrees"]
    s.update({"innerConeAngleDegrees": inner, "outerConeAngleDegrees": outer})
    return s


def windowed_point(position, light_range):
    """A point light whose range ends in KHR's smooth window."""
    return dict(point(position), range=light_range, rangeFalloff="window")


def sun(direction):
    return {"type": "directional", "direction": list(direction), "intensity": [3.0, 3.0, 2.8], "shadowMapSize": 512}


def point(position):
    return {"type": "point", "position": list(position), "intensity": [60.0, 55.0, 50.0], "radius": 0.05,
            "shadowMapSize": 0}


def low_sun_city():
    """A sun 3 degrees above the horizon, from the left and ahead, over the city, seen along the
    avenue to 20 km with reversed depth: the view-fitted shadow box of a grazing light, in haze."""
    e = math.radians(3.0)
    azimuth = math.radians(60.0)  # from the view axis (-z), towards +x
    direction = (math.cos(e) * math.sin(azimuth), -math.sin(e), math.cos(e) * math.cos(azimuth))
    light = {"type": "directional", "direction": list(direction), "intensity": [20.0, 18.0, 15.0],
             "shadowMapSize": 1024}
    camera = {"position": [0.0, 40.0, 300.0], "target": [0.0, 25.0, -20000.0], "near": 0.5, "far": 20000.0,
              "reversedZ": True}
    medium = {"betaR": [5.8e-6, 13.5e-6, 33.1e-6], "betaM": [4e-5, 4e-5, 4e-5], "g": 0.7, "maxDistance": 20000.0}
    return scene(light, gltf="hard_city.gltf", medium=medium, camera=camera)


def scene(light, gltf="hard_cases.gltf", medium=None, camera=None):
    cam = {"position": list(EYE), "target": list(TARGET), "up": [0, 1, 0], "fovYDegrees": FOV,
           "near": 0.1, "far": 60.0, "reversedZ": False, "infiniteFar": False}
    cam.update(camera or {})
    med = {"betaR": [0.002, 0.004, 0.008], "betaM": [0.03, 0.03, 0.03], "g": 0.6, "sigmaA": [0, 0, 0],
           "phase": "cornette-shanks", "maxDistance": 60.0}
    med.update(medium or {})
    s = {"camera": cam, "light": light, "medium": med, "sky": {"color": [0.05, 0.06, 0.09]},
         "ambient": [0.2, 0.2, 0.22], "exposure": 1.5}
    if gltf:
        s["gltf"] = gltf
    return s


def cases():
    w, h = SUITE
    px = ((32.5 / w) * 2 - 1, (18.5 / h) * 2 - 1)
    # Camera exactly on the surface of a cone that lights the scene in front of it: the axis is the
    # direction from the apex to the camera, turned 30 degrees towards the scene.
    a = math.radians(30.0)
    apex = add(EYE, (0.0, 3.0, 2.0))
    u = norm(sub(EYE, apex))
    w = norm(sub(TARGET, apex))
    v = norm(sub(w, mul(u, dot(w, u))))
    axis = norm(add(mul(u, math.cos(a)), mul(v, math.sin(a))))
    return {
        "light_center": scene(spot(through_ndc(0, 0, 5), (0, -1, -0.3))),
        "light_corner": scene(spot(through_ndc(-1, -1, 6), (0.2, -1, 0))),
        "light_on_edge": scene(spot(through_ndc(1, 0, 6), (-0.3, -1, 0))),
        "light_off_screen": scene(spot(through_ndc(2.5, 0.3, 6), (-0.5, -1, 0))),
        "light_behind_camera": scene(spot(add(sub(EYE, mul(FORWARD, 3)), (0, 1, 0)), FORWARD, 40)),
        "spot_at_camera": scene(spot(EYE, FORWARD, 30)),
        "point_at_camera": scene(point(EYE)),
        "ray_through_point_light": scene(point(through_ndc(px[0], px[1], 4))),
        "sun_along_view": scene(sun(FORWARD)),
        "sun_into_view": scene(sun(mul(FORWARD, -1))),
        "sun_across_view": scene(sun((1, 0, 0))),
        "camera_inside_cone": scene(spot(add(EYE, (0, 3, 0)), (0, -1, -0.4), 60)),
        "camera_on_cone": scene(spot(apex, axis, 30)),
        "sky_far_plane": scene(spot((0.3, 6, 0.2), (0, -1, 0)), gltf=None),
        "sky_infinite_far": scene(sun((0.35, -1, -0.25)), camera={"infiniteFar": True}),
        "reversed_z": scene(spot((0.3, 6, 0.2), (0, -1, 0)), camera={"reversedZ": True}),
        "reversed_infinite": scene(spot((0.3, 6, 0.2), (0, -1, 0)), camera={"reversedZ": True, "infiniteFar": True}),
        "thin_medium_km": scene(sun((0.35, -1, -0.25)), camera={"far": 8000.0},
                                medium={"betaR": [2e-6, 4e-6, 8e-6], "betaM": [4e-6, 4e-6, 4e-6], "maxDistance": 8000.0}),
        "dense_medium": scene(spot((0.3, 6, 0.2), (0, -1, 0)), medium={"betaM": [1.0, 1.0, 1.0]}),
        "zero_extinction_channel": scene(spot((0.3, 6, 0.2), (0, -1, 0)),
                                         medium={"betaR": [0, 0.004, 0.008], "betaM": [0, 0.03, 0.03]}),
        "shadow_map_not_pow2": scene(dict(spot((0.3, 6, 0.2), (0, -1, 0)), shadowMapSize=100)),
        "low_sun_city": low_sun_city(),
        # Issue #25's light shapes: a soft-edged spot in view whose penumbra spans most of its cone,
        # and a windowed point light on a pixel's ray whose range ends a few metres from the camera.
        "soft_spot_center": scene(soft_spot(through_ndc(0, 0, 5), (0, -1, -0.3), 10.0, 35.0)),
        "windowed_point_on_ray": scene(windowed_point(through_ndc(px[0], px[1], 4), 3.0)),
        # A cube-shadowed point light on screen inside a small cage, the camera a few metres outside.
        "point_in_cage": dict(scene(dict(point(CAGE_LIGHT), shadowMapSize=512), gltf="hard_cage.gltf",
                                    camera=cage_camera(),
                                    medium={"betaR": [0, 0, 0], "betaM": [0.1, 0.1, 0.1], "g": 0.0,
                                            "phase": "isotropic"}),
                              ambient=[0.02, 0.02, 0.022], exposure=0.3),
        # The same cage and light from 6 m: the cage a third of the screen's height, its bars a
        # pixel or two wide at 320x180, so that the light's glow and the bars' shadows share the
        # few pixels around the light's screen position.
        "point_in_small_cage": dict(scene(dict(point(CAGE_LIGHT), shadowMapSize=512),
                                          gltf="hard_cage.gltf", camera=cage_camera(distance=6.0),
                                          medium={"betaR": [0, 0, 0], "betaM": [0.1, 0.1, 0.1],
                                                  "g": 0.0, "phase": "isotropic"}),
                                    ambient=[0.02, 0.02, 0.022], exposure=0.3),
    }


def main():
    out = Path(sys.argv[1] if len(sys.argv) > 1 else "scenes/hard")
    out.mkdir(parents=True, exist_ok=True)
    write_gltf(out / "hard_cases.gltf", open_scene_quads())
    write_gltf(out / "hard_city.gltf", city_quads())
    write_gltf(out / "hard_cage.gltf", cage_quads())
    for name, s in cases().items():
        (out / f"{name}.json").write_text(json.dumps(s, indent=2) + "\n")
        print(out / f"{name}.json")


if __name__ == "__main__":
    main()
