#!/usr/bin/env python3
"""Writes README.md's feature table from the conformance run (docs/conformance.tsv, written by
`lancer conformance --report docs/conformance`): for each POV-Ray feature group, the sample
scenes that use it (their .pov text names one of the group's keywords), how many of those
lancer renders at SSIM >= 0.95 against POV-Ray, whether lancer warned about one of the group's
keywords, and a few scenes that show it. Replaces the text between the feature-table markers.

    scripts/readme_features.py [--scenes /usr/share/povray-3.7/scenes] [--check]

--check exits 1 when README.md is not what the script would write (for CI or a review).
"""
import argparse
import csv
import os
import re
import sys

GROUPS = [
    ("Cameras: perspective, orthographic, fisheye, panoramic, ...", r"camera"),
    ("Focal blur", r"aperture|focal_point"),
    ("Point lights and spotlights", r"light_source|spotlight"),
    ("Area lights", r"area_light"),
    ("Light groups, projected_through", r"light_group|projected_through"),
    ("Spheres, boxes, cylinders, cones, planes, tori", r"sphere|box|cylinder|cone|plane|torus"),
    ("CSG: union, intersection, difference, merge", r"union|intersection|difference|merge"),
    ("Blobs", r"blob"),
    ("Meshes (mesh, mesh2)", r"mesh2?"),
    ("Height fields", r"height_field"),
    ("Lathe, sor, prism", r"lathe|sor|prism"),
    ("Sphere sweeps", r"sphere_sweep"),
    ("Bicubic patches", r"bicubic_patch"),
    ("Isosurfaces and parametric objects", r"isosurface|parametric"),
    ("Polynomials (quadric, cubic, quartic, poly)", r"quadric|cubic|quartic|poly"),
    ("Superellipsoids", r"superellipsoid"),
    ("Julia fractals", r"julia_fractal"),
    ("Text (TrueType fonts)", r"text"),
    ("Pigment patterns and colour maps", r"pigment|color_map|colour_map"),
    ("Normals (bumps, ripples, waves, ...)", r"normal"),
    ("Finishes (phong, specular, reflection, ...)", r"finish"),
    ("Image maps and bump maps", r"image_map|bump_map"),
    ("Layered, mapped and patterned textures", r"texture_map|material_map|pigment_map"),
    ("Turbulence and warps", r"turbulence|warp"),
    ("Interior: refraction, ior, dispersion", r"ior|refraction|dispersion"),
    ("Fog", r"fog"),
    ("Rainbows", r"rainbow"),
    ("Sky spheres", r"sky_sphere"),
    ("Media (participating media)", r"media"),
    ("Photons", r"photons"),
    ("Radiosity", r"radiosity"),
    ("Subsurface scattering", r"subsurface"),
    ("Macros and loops", r"#macro|#while|#for"),
    ("File I/O (#fopen, #read, #write)", r"#fopen"),
    ("Splines", r"spline"),
    ("User functions", r"function"),
    ("trace() and other object functions", r"trace|inside"),
    ("Animation (clock)", r"clock"),
]

BEGIN = "<!-- feature table: written by scripts/readme_features.py from docs/conformance.tsv -->"
END = "<!-- end of feature table -->"


def keyword_re(alts):
    parts = []
    for a in alts.split("|"):
        if a.startswith("#"):
            parts.append(re.escape(a[0]) + r"\s*" + a[1:] + r"\b")
        else:
            parts.append(r"\b" + a + r"\b")
    return re.compile("|".join(parts))


def strip_comments(text):
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    return re.sub(r"//[^\n]*", " ", text)


def table(rows, scenes_dir):
    counted = [r for r in rows if r["result"] != "povray-failed"]
    texts = {}
    for r in counted:
        try:
            with open(os.path.join(scenes_dir, r["scene"]), encoding="latin-1") as f:
                texts[r["scene"]] = strip_comments(f.read())
        except OSError:
            texts[r["scene"]] = ""
    good_all = sum(r["result"] == "ssim>=0.95" for r in counted)
    out = [
        BEGIN,
        "",
        f"From the last conformance run (docs/conformance.md): {good_all} of {len(counted)} "
        "sample scenes that POV-Ray renders come out at SSIM >= 0.95 against POV-Ray's picture "
        "(160x120, no anti-aliasing). A feature's scenes are the sample scenes whose text uses "
        "one of its keywords; *warned* lists the group's keywords lancer named as not drawn. "
        "Scenes with random features (crand, jitter, photons, radiosity) cannot match pixel "
        "for pixel and count against their groups here (docs/known-differences.tsv).",
        "",
        "| feature | supported | scenes at SSIM >= 0.95 | warned | scenes that show it |",
        "| --- | --- | --- | --- | --- |",
    ]
    for name, alts in GROUPS:
        rx = keyword_re(alts)
        words = {a.lstrip("#") for a in alts.split("|")}
        using = [r for r in counted if rx.search(texts[r["scene"]])]
        if not using:
            continue
        good = [r for r in using if r["result"] == "ssim>=0.95"]
        warned = sorted({m.strip() for r in using for m in r["missing"].split(",")
                         if m.strip() in words})
        share = len(good) / len(using)
        if not good:
            status = "no"
        elif share >= 0.8 and not warned:
            status = "yes"
        else:
            status = "partly"
        shown = sorted(good, key=lambda r: (-float(r["ssim"] or 0), len(r["scene"])))[:3]
        out.append(
            f"| {name} | {status} | {len(good)} of {len(using)} | {', '.join(warned) or '—'} | "
            + ", ".join(f"`{r['scene']}`" for r in shown)
            + " |"
        )
    out += ["", END]
    return "\n".join(out)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--scenes", default="/usr/share/povray-3.7/scenes")
    ap.add_argument("--tsv", default="docs/conformance.tsv")
    ap.add_argument("--readme", default="README.md")
    ap.add_argument("--check", action="store_true")
    a = ap.parse_args()
    with open(a.tsv, newline="") as f:
        rows = list(csv.DictReader(f, delimiter="\t"))
    new_table = table(rows, a.scenes)
    with open(a.readme) as f:
        readme = f.read()
    if BEGIN not in readme or END not in readme:
        sys.exit(f"{a.readme} has no feature-table markers")
    head, rest = readme.split(BEGIN, 1)
    _, tail = rest.split(END, 1)
    updated = head + new_table + tail
    if a.check:
        sys.exit(0 if updated == readme else 1)
    with open(a.readme, "w") as f:
        f.write(updated)


if __name__ == "__main__":
    main()
