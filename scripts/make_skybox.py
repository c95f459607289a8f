#!/usr/bin/env python3
"""Write scenes/sky.png: a deterministic equirectangular sky panorama.

Standard library only (zlib, struct).  The image is 1024x512, 8-bit RGB,
no gAMA/sRGB chunk (POV-Ray 3.7 then decodes it as sRGB).

Layout follows POV-Ray's spherical image mapping (image_map map_type 1):
  * column u = 0 (left edge) is the +x direction, u increases towards +z
    (u = 0.25 -> +z, 0.5 -> -x, 0.75 -> -z);
  * the top row is straight up (+y), the bottom row straight down,
    the middle row is the horizon.

Contents, so that reflections and the inverted view through glass are
easy to recognise:
  * sky gradient from pale horizon to deep blue zenith, a few soft clouds;
  * a sun (az 115 deg, el 22 deg), i.e. ahead and slightly left of a
    camera looking down +z;
  * a snow-capped mountain range, bluish, all around the horizon;
  * nearer green hills;
  * a red/white striped tower straight ahead (+z);
  * green/yellow fields below the horizon, a blue lake towards -x,
    darkening towards the nadir.

Usage: python3 scripts/make_skybox.py [output.png]
"""
import math
import os
import struct
import sys
import zlib

W, H = 1024, 512
TAU = 2.0 * math.pi
DEG = math.pi / 180.0


def clamp01(x):
    return 0.0 if x < 0.0 else (1.0 if x > 1.0 else x)


def smoothstep(e0, e1, x):
    t = clamp01((x - e0) / (e1 - e0))
    return t * t * (3.0 - 2.0 * t)


def mix(a, b, t):
    return (a[0] + (b[0] - a[0]) * t,
            a[1] + (b[1] - a[1]) * t,
            a[2] + (b[2] - a[2]) * t)


def angdiff(a, b):
    """Signed smallest difference a-b of two azimuths, in (-pi, pi]."""
    d = (a - b) % TAU
    return d - TAU if d > math.pi else d


# Half a pixel in elevation: width of the soft edges.
PIX = math.pi / H

# Ridge profiles: periodic in azimuth (integer frequencies), in radians of
# elevation.
MOUNT_TERMS = [(3, 0.090, 0.3), (5, 0.065, 1.7), (8, 0.045, 4.1),
               (13, 0.025, 2.2), (21, 0.014, 5.3), (34, 0.007, 0.9)]
HILL_TERMS = [(2, 0.022, 2.0), (7, 0.016, 0.4), (11, 0.010, 3.3),
              (17, 0.005, 1.1)]


def mountain_height(az):
    h = 0.19
    for k, a, p in MOUNT_TERMS:
        h += a * math.sin(k * az + p)
    return h


def hill_height(az):
    h = 0.06
    for k, a, p in HILL_TERMS:
        h += a * math.sin(k * az + p)
    return max(h, 0.004)


SUN_AZ, SUN_EL, SUN_R = 115 * DEG, 22 * DEG, 2.6 * DEG
SUN_DIR = (math.cos(SUN_EL) * math.cos(SUN_AZ), math.sin(SUN_EL),
           math.cos(SUN_EL) * math.sin(SUN_AZ))

# Clouds: (azimuth, elevation, half-width az, half-height el) in degrees;
# each cloud is a few overlapping soft ellipses.
CLOUDS = [(40, 22, 14, 3.0), (50, 25, 8, 3.5), (30, 24, 6, 3.0),
          (170, 35, 16, 3.5), (182, 38, 9, 4.0), (160, 37, 7, 3.0),
          (250, 20, 18, 2.5), (262, 23, 8, 3.5), (243, 22, 6, 3.0),
          (320, 42, 12, 3.5), (328, 45, 7, 3.5),
          (75, 52, 10, 3.0), (135, 18, 10, 2.0), (140, 20, 5, 2.5),
          (10, 60, 14, 4.0), (215, 65, 16, 4.0)]

TOWER_AZ, TOWER_HALF_W, TOWER_TOP = 90 * DEG, 0.9 * DEG, 16 * DEG

LAKE_AZ, LAKE_EL, LAKE_RA, LAKE_RE = 180 * DEG, -9 * DEG, 30 * DEG, 4.5 * DEG


def sky_colour(az, el):
    t = clamp01(el / (0.5 * math.pi))
    horizon = (0.80, 0.88, 0.97)
    zenith = (0.10, 0.28, 0.72)
    c = mix(horizon, zenith, math.sqrt(t))
    # sun: glow + disc
    d = (math.cos(el) * math.cos(az), math.sin(el), math.cos(el) * math.sin(az))
    cosang = d[0] * SUN_DIR[0] + d[1] * SUN_DIR[1] + d[2] * SUN_DIR[2]
    ang = math.acos(max(-1.0, min(1.0, cosang)))
    glow = math.exp(-ang / (9 * DEG)) * 0.55
    c = mix(c, (1.0, 0.93, 0.70), clamp01(glow))
    # clouds
    cov = 0.0
    for caz, cel, wa, he in CLOUDS:
        da = angdiff(az, caz * DEG) / (wa * DEG)
        de = (el - cel * DEG) / (he * DEG)
        r2 = da * da + de * de
        cov = max(cov, 1.0 - smoothstep(0.55, 1.0, r2))
    if cov > 0.0:
        c = mix(c, (0.97, 0.97, 0.99), 0.9 * cov)
    disc = 1.0 - smoothstep(SUN_R - PIX, SUN_R + PIX, ang)
    c = mix(c, (1.0, 0.98, 0.85), disc)
    return c


def colour_at(az, el):
    # ground below the horizon
    if el < 0.0:
        depth = clamp01(-el / (0.5 * math.pi))
        # fields: sectors in azimuth, bands in elevation
        sector = int(math.floor(az / (15 * DEG)))
        band = int(math.floor(-el / (6 * DEG)))
        palette = [(0.30, 0.55, 0.18), (0.50, 0.60, 0.22),
                   (0.24, 0.47, 0.16), (0.66, 0.60, 0.30)]
        c = palette[(sector + 2 * band) % 4]
        # a brown path straight ahead (+z) leading to the tower
        if abs(angdiff(az, TOWER_AZ)) < (1.2 + 10.0 * depth) * DEG:
            c = (0.50, 0.36, 0.22)
        # a lake towards -x
        da = angdiff(az, LAKE_AZ) / LAKE_RA
        de = (el - LAKE_EL) / LAKE_RE
        if da * da + de * de < 1.0:
            c = mix((0.15, 0.35, 0.65), (0.45, 0.65, 0.85), clamp01(-de))
        # darken towards the nadir, haze at the horizon
        c = mix(c, (0.12, 0.16, 0.10), smoothstep(0.25, 1.0, depth))
        c = mix(c, (0.70, 0.78, 0.80), 0.35 * (1.0 - smoothstep(0.0, 0.05, depth)))
        return c
    c = sky_colour(az, el)
    # far mountains with snow caps
    mh = mountain_height(az)
    m = 1.0 - smoothstep(mh - PIX, mh + PIX, el)
    if m > 0.0:
        rock = mix((0.42, 0.46, 0.60), (0.60, 0.64, 0.74), clamp01(el / 0.4))
        snowline = 0.27 + 0.02 * math.sin(9 * az)
        snow = smoothstep(snowline - PIX, snowline + PIX, el)
        mc = mix(rock, (0.95, 0.96, 1.0), snow)
        c = mix(c, mc, m)
    # near green hills
    hh = hill_height(az)
    k = 1.0 - smoothstep(hh - PIX, hh + PIX, el)
    if k > 0.0:
        hc = mix((0.20, 0.50, 0.16), (0.35, 0.62, 0.22), clamp01(el / 0.08))
        c = mix(c, hc, k)
    # a red/white striped tower straight ahead (+z)
    da = abs(angdiff(az, TOWER_AZ))
    if da < TOWER_HALF_W + PIX and el < TOWER_TOP + PIX:
        cover = (1.0 - smoothstep(TOWER_HALF_W - PIX, TOWER_HALF_W + PIX, da)) * \
                (1.0 - smoothstep(TOWER_TOP - PIX, TOWER_TOP + PIX, el))
        stripe = int(math.floor(el / (2.0 * DEG))) % 2
        tc = (0.85, 0.10, 0.08) if stripe == 0 else (0.97, 0.97, 0.95)
        if el > TOWER_TOP - 1.2 * DEG:
            tc = (1.0, 0.85, 0.2)  # lamp
        c = mix(c, tc, cover)
    return c


def to_byte(x):
    return int(clamp01(x) * 255.0 + 0.5)


def png_chunk(tag, data):
    body = tag + data
    return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)


def encode_png(width, height, rows):
    raw = bytearray()
    for row in rows:
        raw.append(2)  # filter "Up" (gradients compress well)
        raw.extend(row)
    ihdr = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + png_chunk(b"IHDR", ihdr)
            + png_chunk(b"IDAT", zlib.compress(bytes(raw), 9))
            + png_chunk(b"IEND", b""))


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "scenes", "sky.png")
    # Colours are designed as display (sRGB-encoded) values in [0, 1].
    prev = bytes(W * 3)
    rows = []
    for r in range(H):
        v = 1.0 - (r + 0.5) / H
        el = (v - 0.5) * math.pi
        pix = bytearray()
        for col in range(W):
            u = (col + 0.5) / W
            az = u * TAU
            c = colour_at(az, el)
            pix.extend(to_byte(ch) for ch in c)
        # "Up" filter
        rows.append(bytes((pix[i] - prev[i]) & 0xFF for i in range(W * 3)))
        prev = bytes(pix)
    data = encode_png(W, H, rows)
    with open(out, "wb") as f:
        f.write(data)
    print("wrote %s (%dx%d, %d bytes)" % (os.path.normpath(out), W, H, len(data)))


if __name__ == "__main__":
    main()
