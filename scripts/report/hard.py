"""The 'The hard-case suite' section: every hard case's error beside the bound
tests/host/hard_suite_test.cpp asserts."""
import re
from pathlib import Path

from .common import fmt


def hard_section(hard):
    out = []
    p = out.append
    p("## The hard-case suite\n")
    bounds = {}
    test = Path("tests/host/hard_suite_test.cpp").read_text()
    # Bound{epipolar, bruteForce, ...}: the first two fields are this table's.
    for name, fields in re.findall(r'\{"(\w+)", \{([\d., ]+)\}\}', test):
        bounds[name] = tuple(float(x) for x in fields.split(","))[:2]
    default = tuple(float(x) for x in re.search(r"kDefault\{([\d., ]+)\}", test).group(1).split(","))[:2]
    w, h = hard[0]["size"]
    p(f"Every hard case of [model.md](model.md#hard-cases) as a scene (`scenes/hard`, from `tools/make_scenes/make_hard_cases.py`), {w}x{h}, balanced "
      "profile. `test_hard_suite` asserts finite pixels and the bound below for each (mean relative error); thin "
      "media must stay within 1% of float64. A point light without a cube shadow map is unshadowed in the "
      "plugin but shadowed in the reference, so its cases count the missing shadows as error.\n")
    def named_bounds(start, end):
        block = test.split(start)[1].split(end)[0]
        return ({n: float(v) for n, v in re.findall(r'\{"(\w+)", ([\d.]+)\}', block)},
                float(re.search(end + r" = ([\d.]+)", test).group(1)))
    # The methods beside epipolar and brute force, each with its bounds in the test.
    others = [("planes", *named_bounds("kPlanesBounds", "kPlanesDefault")),
              ("beam-tree-analytic", *named_bounds("kBeamTreeBounds", "kBeamTreeDefault")),
              ("beam-tree-sampling", *named_bounds("kBeamTreeSamplingBounds", "kBeamTreeSamplingDefault"))]
    header = "| case | epipolar error | bound | brute-force error | bound |"
    for name, _, _ in others:
        header += f" {name} error | bound |"
    p(header + " non-finite |")
    p("|---" * (5 + 2 * len(others) + 1) + "|")
    for scene in sorted({r["scene"] for r in hard}):
        epi = next(r for r in hard if r["scene"] == scene and r["method"] == "epipolar")
        bf = next(r for r in hard if r["scene"] == scene and r["method"] == "brute-force")
        b = bounds.get(scene, default)
        nonfinite = epi['nonFinite'] + bf['nonFinite']
        line = (f"| {scene.replace('_', ' ')} | {fmt(epi['error']['meanRelative'])} | {b[0]} | "
                f"{fmt(bf['error']['meanRelative'])} | {b[1]} |")
        for name, table, fallback in others:
            # "slices": the planes method's name in runs made before it was renamed.
            names = ("planes", "slices") if name == "planes" else (name,)
            r = next((r for r in hard if r["scene"] == scene and r["method"] in names), None)
            if r:
                nonfinite += r['nonFinite']
                line += f" {fmt(r['error']['meanRelative'])} | {table.get(scene, fallback)} |"
            else:
                line += " - | - |"  # not run: a directional light (beam tree), a cube map (planes, beam tree)
        p(line + f" {nonfinite} |")
    p("\nThe beam-tree methods run on the point and spot cases only (\"-\": a directional light). The host "
      "gives them one box per connected part of the scene's glTF primitives. A point light's cube shadow map "
      "(point in cage) is sampled by epipolar and brute force only.\n")
    p("`froxels` runs in `test_hard_suite` too, at 2-pixel columns and 64 slices (froxels-hdrp's density at 1920x1080), held to its own bounds there (`kFroxelBounds`). A point or spot light's froxel takes its slice of the column's ray in closed form (the unshadowed Lin over the part the light reaches, times the shadow and color at its middle), where a point sample per froxel missed or overshot the inverse square's peak: measured on lavapipe 0.029 point at camera (0.546 point-sampled), 0.089 spot at camera (0.538), 0.195 light on edge (0.624), 0.501 dense medium (0.578), 0.345 on the reversed-z cases (0.400), 0.318 light center (0.348), 0.094 point in cage (0.110), 0.036 sun into view and at most 0.0101 on the sun and thin-medium cases. What stays is the grid's spreading of a thin shaft or a cone's edge over its froxel (docs/methods.md, \"froxels\").\n")
    return out
