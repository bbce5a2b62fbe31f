#!/usr/bin/python3
"""Deterministic procedural asset generator for rrc.

Writes (overwriting) into <repo>/assets/ (or the directory given as argv[1]):
  temple.glb           Parthenon-like colonnade (high depth complexity)
  character.glb        skinned procedural humanoid "heroine" with a "run" clip
  env/{px,nx,py,ny,pz,nz}.png + env/README.md   procedural sky cube map
  bump.png             256x256 8-bit grayscale hammered-metal height map
  scenes.md            description of the assets (generated from the data)
  LICENSE.md           CC0 statement

Standard library only (struct, json, zlib, math).  No randomness except an
integer hash, so every run produces the same bytes (given the same zlib).
"""

import json
import math
import os
import struct
import sys
import zlib

# ---------------------------------------------------------------------------
# small math helpers
# ---------------------------------------------------------------------------


def v_add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def v_sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def v_mul(a, s):
    return (a[0] * s, a[1] * s, a[2] * s)


def v_dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def v_cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def v_len(a):
    return math.sqrt(v_dot(a, a))


def v_norm(a):
    n = v_len(a)
    return (a[0] / n, a[1] / n, a[2] / n)


def clamp(x, lo, hi):
    return lo if x < lo else hi if x > hi else x


def smoothstep(e0, e1, x):
    t = clamp((x - e0) / (e1 - e0), 0.0, 1.0)
    return t * t * (3.0 - 2.0 * t)


def lerp(a, b, t):
    return a + (b - a) * t


def f32(x):
    return struct.unpack('<f', struct.pack('<f', x))[0]


def r6(x):
    """Round for JSON output (keeps the JSON short and stable)."""
    v = round(x, 6)
    return 0.0 if v == 0 else v


def quat_axis_angle(axis, ang):
    ax = v_norm(axis)
    s = math.sin(ang * 0.5)
    return (ax[0] * s, ax[1] * s, ax[2] * s, math.cos(ang * 0.5))


def quat_mul(a, b):
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return (aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw,
            aw * bw - ax * bx - ay * by - az * bz)


def quat_normalize(q):
    n = math.sqrt(sum(c * c for c in q))
    return tuple(c / n for c in q)


def quat_from_basis(x, y, z):
    """Quaternion (x,y,z,w) of the rotation whose matrix columns are x, y, z."""
    m00, m10, m20 = x
    m01, m11, m21 = y
    m02, m12, m22 = z
    tr = m00 + m11 + m22
    if tr > 0:
        s = math.sqrt(tr + 1.0) * 2
        w = 0.25 * s
        qx = (m21 - m12) / s
        qy = (m02 - m20) / s
        qz = (m10 - m01) / s
    elif m00 > m11 and m00 > m22:
        s = math.sqrt(1.0 + m00 - m11 - m22) * 2
        w = (m21 - m12) / s
        qx = 0.25 * s
        qy = (m01 + m10) / s
        qz = (m02 + m20) / s
    elif m11 > m22:
        s = math.sqrt(1.0 + m11 - m00 - m22) * 2
        w = (m02 - m20) / s
        qx = (m01 + m10) / s
        qy = 0.25 * s
        qz = (m12 + m21) / s
    else:
        s = math.sqrt(1.0 + m22 - m00 - m11) * 2
        w = (m10 - m01) / s
        qx = (m02 + m20) / s
        qy = (m12 + m21) / s
        qz = 0.25 * s
    return quat_normalize((qx, qy, qz, w))


def look_at_quat(eye, target, up=(0.0, 1.0, 0.0)):
    """glTF cameras look down their local -Z with +Y up."""
    f = v_norm(v_sub(target, eye))
    z = v_mul(f, -1.0)
    x = v_norm(v_cross(up, z))
    y = v_cross(z, x)
    return quat_from_basis(x, y, z)


# ---------------------------------------------------------------------------
# deterministic noise
# ---------------------------------------------------------------------------


def hash_u32(x, y, seed):
    n = (x * 374761393 + y * 668265263 + seed * 2246822519 + 0x9E3779B9) & 0xFFFFFFFF
    n = ((n ^ (n >> 13)) * 1274126177) & 0xFFFFFFFF
    n = ((n ^ (n >> 16)) * 2246822519) & 0xFFFFFFFF
    return n ^ (n >> 15)


def hash01(x, y, seed):
    return hash_u32(x, y, seed) / 4294967296.0


class ValueNoise:
    """2-D value noise on a 256x256 lattice table (wraps with period 256, or a
    smaller period when requested so textures tile)."""

    def __init__(self, seed):
        self.t = [hash01(i & 255, i >> 8, seed) for i in range(65536)]

    def noise(self, x, y, period=256):
        xi = math.floor(x)
        yi = math.floor(y)
        xf = x - xi
        yf = y - yi
        x0 = xi % period
        y0 = yi % period
        x1 = (x0 + 1) % period
        y1 = (y0 + 1) % period
        t = self.t
        a = t[(y0 << 8) | x0]
        b = t[(y0 << 8) | x1]
        c = t[(y1 << 8) | x0]
        d = t[(y1 << 8) | x1]
        u = xf * xf * (3.0 - 2.0 * xf)
        v = yf * yf * (3.0 - 2.0 * yf)
        ab = a + (b - a) * u
        cd = c + (d - c) * u
        return ab + (cd - ab) * v

    def fbm(self, x, y, octaves, period=256, gain=0.5):
        s = 0.0
        amp = 0.5
        norm = 0.0
        p = period
        for _ in range(octaves):
            s += amp * self.noise(x, y, p)
            norm += amp
            x *= 2.0
            y *= 2.0
            p = min(256, p * 2)
            amp *= gain
        return s / norm


# ---------------------------------------------------------------------------
# PNG writer (zlib + struct + crc32)
# ---------------------------------------------------------------------------


def _png_chunk(tag, data):
    c = struct.pack('>I', len(data)) + tag + data
    return c + struct.pack('>I', zlib.crc32(tag + data) & 0xFFFFFFFF)


def _paeth(a, b, c):
    p = a + b - c
    pa = abs(p - a)
    pb = abs(p - b)
    pc = abs(p - c)
    if pa <= pb and pa <= pc:
        return a
    if pb <= pc:
        return b
    return c


def encode_png(width, height, channels, pixels):
    """pixels: bytes/bytearray, row-major, top row first, `channels` 1 (gray) or 3 (RGB)."""
    color_type = {1: 0, 3: 2, 4: 6}[channels]
    stride = width * channels
    raw = bytearray()
    prev = bytearray(stride)
    for y in range(height):
        row = pixels[y * stride:(y + 1) * stride]
        cands = []
        # filter 0 (none), 1 (sub), 2 (up), 4 (paeth); pick minimum sum of |signed bytes|
        f1 = bytearray(stride)
        f2 = bytearray(stride)
        f4 = bytearray(stride)
        for i in range(stride):
            a = row[i - channels] if i >= channels else 0
            b = prev[i]
            c = prev[i - channels] if i >= channels else 0
            x = row[i]
            f1[i] = (x - a) & 255
            f2[i] = (x - b) & 255
            f4[i] = (x - _paeth(a, b, c)) & 255
        for ftype, data in ((0, bytes(row)), (1, f1), (2, f2), (4, f4)):
            score = sum(v if v < 128 else 256 - v for v in data)
            cands.append((score, ftype, data))
        cands.sort(key=lambda t: (t[0], t[1]))
        raw.append(cands[0][1])
        raw += cands[0][2]
        prev = bytearray(row)
    ihdr = struct.pack('>IIBBBBB', width, height, 8, color_type, 0, 0, 0)
    return (b'\x89PNG\r\n\x1a\n' + _png_chunk(b'IHDR', ihdr) +
            _png_chunk(b'IDAT', zlib.compress(bytes(raw), 9)) + _png_chunk(b'IEND', b''))


# ---------------------------------------------------------------------------
# glTF / GLB builder
# ---------------------------------------------------------------------------

FLOAT, UINT, USHORT, UBYTE = 5126, 5125, 5123, 5121
ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 34962, 34963
_FMT = {FLOAT: 'f', UINT: 'I', USHORT: 'H', UBYTE: 'B'}
_NCOMP = {'SCALAR': 1, 'VEC2': 2, 'VEC3': 3, 'VEC4': 4, 'MAT4': 16}


class GltfBuilder:
    def __init__(self, generator='rrc scripts/make_assets.py'):
        self.bin = bytearray()
        self.doc = {
            'asset': {'version': '2.0', 'generator': generator,
                      'copyright': 'CC0 1.0 (public domain dedication)'},
            'scene': 0,
            'scenes': [],
            'nodes': [],
            'meshes': [],
            'materials': [],
            'accessors': [],
            'bufferViews': [],
            'buffers': [],
        }

    def _list(self, key):
        return self.doc.setdefault(key, [])

    def add(self, key, obj):
        lst = self._list(key)
        lst.append(obj)
        return len(lst) - 1

    def buffer_view(self, data, target=None):
        while len(self.bin) % 4:
            self.bin.append(0)
        off = len(self.bin)
        self.bin += data
        bv = {'buffer': 0, 'byteOffset': off, 'byteLength': len(data)}
        if target is not None:
            bv['target'] = target
        return self.add('bufferViews', bv)

    def accessor(self, values, ctype, atype, target=None, minmax=False, name=None):
        n = _NCOMP[atype]
        assert len(values) % n == 0
        count = len(values) // n
        data = struct.pack('<%d%s' % (len(values), _FMT[ctype]), *values)
        bv = self.buffer_view(data, target)
        acc = {'bufferView': bv, 'componentType': ctype, 'count': count, 'type': atype}
        if minmax:
            if ctype == FLOAT:
                vals = struct.unpack('<%df' % len(values), data)  # float32-rounded
            else:
                vals = values
            mn = [min(vals[i::n]) for i in range(n)]
            mx = [max(vals[i::n]) for i in range(n)]
            acc['min'] = mn
            acc['max'] = mx
        if name:
            acc['name'] = name
        return self.add('accessors', acc)

    def image_png(self, png_bytes, name):
        bv = self.buffer_view(png_bytes)
        return self.add('images', {'name': name, 'bufferView': bv, 'mimeType': 'image/png'})

    def to_glb(self):
        while len(self.bin) % 4:
            self.bin.append(0)
        self.doc['buffers'] = [{'byteLength': len(self.bin)}]
        doc = {k: v for k, v in self.doc.items() if v != []}
        js = json.dumps(doc, separators=(',', ':')).encode('utf-8')
        while len(js) % 4:
            js += b' '
        total = 12 + 8 + len(js) + 8 + len(self.bin)
        out = bytearray()
        out += struct.pack('<4sII', b'glTF', 2, total)
        out += struct.pack('<I4s', len(js), b'JSON') + js
        out += struct.pack('<I4s', len(self.bin), b'BIN\x00') + self.bin
        assert len(out) == total
        return bytes(out)


# ---------------------------------------------------------------------------
# mesh building
# ---------------------------------------------------------------------------


class Mesh:
    """Indexed triangle list with per-vertex position, normal, uv (+optional
    tangent, joints, weights)."""

    def __init__(self):
        self.pos = []
        self.nrm = []
        self.uv = []
        self.tan = []
        self.joints = []
        self.weights = []
        self.idx = []

    def vert(self, p, n, uv, tan=None):
        self.pos.append(p)
        self.nrm.append(n)
        self.uv.append(uv)
        if tan is not None:
            self.tan.append(tan)
        return len(self.pos) - 1

    def tri_oriented(self, a, b, c, ref):
        """Adds triangle a,b,c wound counter-clockwise as seen from direction `ref`."""
        pa, pb, pc = self.pos[a], self.pos[b], self.pos[c]
        n = v_cross(v_sub(pb, pa), v_sub(pc, pa))
        if v_len(n) < 1e-12:
            return  # skip degenerate triangles
        if v_dot(n, ref) < 0:
            b, c = c, b
        self.idx += (a, b, c)

    def quad(self, corners, n, uvs, tan=None):
        """corners CCW seen from the normal side."""
        i = [self.vert(corners[k], n, uvs[k], tan) for k in range(4)]
        self.tri_oriented(i[0], i[1], i[2], n)
        self.tri_oriented(i[0], i[2], i[3], n)

    def box_axes(self, c, ax, ay, az, tile=2.0):
        """Box centred at c with three orthogonal half-axis vectors."""
        for sgn, fa, u, v in ((1, ax, az, ay), (-1, ax, az, ay), (1, ay, ax, az), (-1, ay, ax, az),
                              (1, az, ax, ay), (-1, az, ax, ay)):
            fc = v_add(c, v_mul(fa, sgn))
            n = v_norm(v_mul(fa, sgn))
            if v_dot(v_cross(u, v), n) < 0:
                u = v_mul(u, -1.0)
            lu = 2 * v_len(u) / tile
            lv = 2 * v_len(v) / tile
            corners = [v_add(fc, v_add(v_mul(u, su), v_mul(v, sv)))
                       for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
            uvs = [(0.0, lv), (lu, lv), (lu, 0.0), (0.0, 0.0)]
            self.quad(corners, n, uvs)

    def box(self, lo, hi, tile=2.0):
        c = tuple((lo[i] + hi[i]) * 0.5 for i in range(3))
        h = tuple((hi[i] - lo[i]) * 0.5 for i in range(3))
        self.box_axes(c, (h[0], 0, 0), (0, h[1], 0), (0, 0, h[2]), tile)

    def tri_count(self):
        return len(self.idx) // 3


def emit_primitive(b, mesh, material, skinned=False):
    pos = [c for p in mesh.pos for c in p]
    nrm = []
    for n in mesh.nrm:
        n = v_norm(n)
        nrm += n
    uv = [c for t in mesh.uv for c in t]
    attrs = {
        'POSITION': b.accessor(pos, FLOAT, 'VEC3', ARRAY_BUFFER, minmax=True),
        'NORMAL': b.accessor(nrm, FLOAT, 'VEC3', ARRAY_BUFFER),
        'TEXCOORD_0': b.accessor(uv, FLOAT, 'VEC2', ARRAY_BUFFER),
    }
    if mesh.tan:
        attrs['TANGENT'] = b.accessor([c for t in mesh.tan for c in t], FLOAT, 'VEC4', ARRAY_BUFFER)
    if skinned:
        attrs['JOINTS_0'] = b.accessor([c for j in mesh.joints for c in j], UBYTE, 'VEC4', ARRAY_BUFFER)
        attrs['WEIGHTS_0'] = b.accessor([c for w in mesh.weights for c in w], FLOAT, 'VEC4', ARRAY_BUFFER)
    ctype = USHORT if len(mesh.pos) <= 65535 else UINT
    ind = b.accessor(list(mesh.idx), ctype, 'SCALAR', ELEMENT_ARRAY_BUFFER)
    return {'attributes': attrs, 'indices': ind, 'material': material, 'mode': 4}


# ---------------------------------------------------------------------------
# textures
# ---------------------------------------------------------------------------

TEX = 256  # ground texture size; the texture spans GROUND_TILE_M metres
GROUND_TILE_M = 8.0


def ground_textures():
    """Returns (albedo_rgb_bytes, normal_rgb_bytes) for a tileable
    paving texture: 2 m x 1 m slabs in running bond (4 x 8 slabs per 8 m tile)."""
    N = TEX
    vn = ValueNoise(11)
    height = [0.0] * (N * N)
    albedo = bytearray(N * N * 3)
    row_h = N // 8      # 32 px = 1 m
    slab_w = N // 4     # 64 px = 2 m
    for y in range(N):
        row = y // row_h
        fy = y - row * row_h
        shift = (slab_w // 2) if (row & 1) else 0
        for x in range(N):
            xs = (x + shift) % N
            col = xs // slab_w
            fx = xs - col * slab_w
            # distance to slab edge in px
            d = min(fx + 0.5, slab_w - fx - 0.5, fy + 0.5, row_h - fy - 0.5)
            groove = smoothstep(1.0, 3.0, d)           # 0 in the joint, 1 on the slab
            tone = hash01(col, row, 5) - 0.5
            tilt_x = (hash01(col, row, 6) - 0.5) * 0.006
            tilt_y = (hash01(col, row, 7) - 0.5) * 0.006
            n_lo = vn.fbm(x / 32.0, y / 32.0, 4, period=8)
            n_hi = vn.noise(x / 4.0, y / 4.0, 64)
            h = groove * (0.6 + tilt_x * (fx - slab_w / 2) + tilt_y * (fy - row_h / 2)
                          + 0.25 * n_lo + 0.06 * n_hi)
            height[y * N + x] = h
            base = (196 + 30 * tone, 182 + 26 * tone, 156 + 20 * tone)
            shade = 0.78 + 0.3 * n_lo + 0.08 * n_hi
            joint = (92, 84, 74)
            for ch in range(3):
                val = lerp(joint[ch], base[ch] * shade, groove)
                albedo[(y * N + x) * 3 + ch] = int(clamp(round(val), 0, 255))
    normal = bytearray(N * N * 3)
    strength = 6.0
    for y in range(N):
        for x in range(N):
            dhdx = (height[y * N + (x + 1) % N] - height[y * N + (x - 1) % N]) * 0.5
            dhdy = (height[((y + 1) % N) * N + x] - height[((y - 1) % N) * N + x]) * 0.5
            # tangent space, +X right, +Y up in the image (glTF / OpenGL convention)
            n = v_norm((-dhdx * strength, dhdy * strength, 1.0))
            for ch in range(3):
                normal[(y * N + x) * 3 + ch] = int(clamp(round((n[ch] * 0.5 + 0.5) * 255), 0, 255))
    return bytes(albedo), bytes(normal)


def bump_map():
    """256x256 tileable hammered-metal height map: jittered Voronoi dimples
    (each dimple is a shallow paraboloid, ridges where dimples meet) + fine grain."""
    N = 256
    cells = 24
    cs = N / cells
    pts = {}
    for cy in range(cells):
        for cx in range(cells):
            jx = 0.15 + 0.7 * hash01(cx, cy, 21)
            jy = 0.15 + 0.7 * hash01(cx, cy, 22)
            depth = 0.75 + 0.5 * hash01(cx, cy, 23)
            pts[(cx, cy)] = ((cx + jx) * cs, (cy + jy) * cs, depth)
    vn = ValueNoise(29)
    out = bytearray(N * N)
    vals = [0.0] * (N * N)
    for y in range(N):
        cy0 = int(y // cs)
        for x in range(N):
            cx0 = int(x // cs)
            best = 1e9
            for oy in (-1, 0, 1):
                for ox in (-1, 0, 1):
                    cx = cx0 + ox
                    cy = cy0 + oy
                    px, py, dep = pts[(cx % cells, cy % cells)]
                    px += (cx - cx % cells) * cs
                    py += (cy - cy % cells) * cs
                    dx = x + 0.5 - px
                    dy = y + 0.5 - py
                    d2 = (dx * dx + dy * dy) / (cs * cs) * dep
                    if d2 < best:
                        best = d2
            h = min(1.0, best * 1.25)
            grain = vn.noise(x / 2.0, y / 2.0, 128) - 0.5
            vals[y * N + x] = 0.12 + 0.78 * h + 0.10 * grain
    for i, v in enumerate(vals):
        out[i] = int(clamp(round(v * 255), 0, 255))
    return bytes(out)


# ---------------------------------------------------------------------------
# environment cube map
# ---------------------------------------------------------------------------

ENV_N = 256
SUN_DIR = v_norm((0.45, 0.42, -0.79))


def face_dir(face, sc, tc):
    """OpenGL cube map: direction for face and (sc, tc) in [-1,1] (GL spec table 8.19)."""
    if face == 'px':
        return (1.0, -tc, -sc)
    if face == 'nx':
        return (-1.0, -tc, sc)
    if face == 'py':
        return (sc, 1.0, tc)
    if face == 'ny':
        return (sc, -1.0, -tc)
    if face == 'pz':
        return (sc, -tc, 1.0)
    return (-sc, -tc, -1.0)  # nz


def sky_color(d, cloud_noise, mtn_noise, rock_noise):
    x, y, z = d
    el = math.asin(clamp(y, -1.0, 1.0))
    az = math.atan2(z, x)
    # mountains: periodic 1-D fbm over azimuth
    u = (az / (2 * math.pi) + 0.5) * 64.0
    m = mtn_noise.fbm(u, 3.5, 6, period=64)
    mh = 0.012 + 0.45 * max(0.0, m - 0.36) ** 1.25
    if y >= 0.0 and el < mh:
        # rock with strata and fine cracks, darker near the peaks' shadows
        r = rock_noise.fbm(az * 120.0, el * 240.0, 4)
        strata = 0.5 + 0.5 * math.sin(el * 900.0 + 6.0 * r)
        k = 0.45 + 0.35 * r + 0.2 * strata
        snow = smoothstep(0.08, 0.11, el) * smoothstep(0.55, 0.7, r + el * 2)
        c = (lerp(88 * k, 235, snow), lerp(96 * k, 240, snow), lerp(92 * k, 250, snow))
        haze = 0.35
        return (lerp(c[0], 190, haze), lerp(c[1], 200, haze), lerp(c[2], 212, haze))
    if y < 0.0:
        # paved ground plane 1.5 m below the viewer: 0.5 m slabs, 2 cm joints, checker
        # tones and fine stone grain
        t = 1.5 / max(-y, 1e-4)
        gx = x * t
        gz = z * t
        dist = math.sqrt(gx * gx + gz * gz)
        sx = gx * 2.0
        sz = gz * 2.0
        ix = math.floor(sx)
        iz = math.floor(sz)
        fx = sx - ix
        fz = sz - iz
        jd = min(fx, 1 - fx, fz, 1 - fz)
        joint = 1.0 - smoothstep(0.03, 0.05, jd)
        chk = 1.0 if ((ix + iz) & 1) else 0.0
        tone = hash01(ix & 0xFFFF, iz & 0xFFFF, 41)
        grain = rock_noise.fbm(gx * 6.0, gz * 6.0, 3) - 0.5
        base = (70 + 120 * chk + 30 * tone + 60 * grain, 78 + 100 * chk + 25 * tone + 55 * grain,
                60 + 80 * chk + 20 * tone + 45 * grain)
        base = (lerp(base[0], 40, joint), lerp(base[1], 38, joint), lerp(base[2], 34, joint))
        k = math.exp(-dist / 90.0)
        avg = (120, 120, 96)
        c = tuple(lerp(avg[i], base[i], k) for i in range(3))
        h = 1.0 - math.exp(-dist / 220.0)
        return (lerp(c[0], 190, h), lerp(c[1], 200, h), lerp(c[2], 212, h))
    # sky gradient
    t = math.sqrt(max(y, 0.0))
    col = [lerp(200, 38, t), lerp(220, 92, t), lerp(240, 196, t)]
    # clouds on a plane above the viewer
    if y > 0.015:
        s = 1.0 / (y + 0.06)
        cx = x * s * 3.0 + 17.0
        cz = z * s * 3.0 + 31.0
        n = cloud_noise.fbm(cx, cz, 6)
        cov = smoothstep(0.48, 0.72, n) * smoothstep(0.015, 0.12, y)
        if cov > 0:
            dn = cloud_noise.fbm(cx + 0.35, cz + 0.35, 3)
            shade = clamp(0.75 + (n - dn) * 2.5, 0.55, 1.0)
            cc = (255 * shade, 252 * shade, 248 * shade)
            col = [lerp(col[i], cc[i], cov) for i in range(3)]
    # sun: disk (~2 deg radius) plus glow
    cs = v_dot(d, SUN_DIR)
    glow = max(cs, 0.0)
    col[0] += 255 * (0.55 * glow ** 64 + 0.2 * glow ** 8)
    col[1] += 215 * (0.55 * glow ** 64 + 0.2 * glow ** 8)
    col[2] += 150 * (0.55 * glow ** 64 + 0.2 * glow ** 8)
    if cs > math.cos(math.radians(2.0)):
        col = [255, 253, 240]
    return tuple(col)


def env_faces():
    cloud = ValueNoise(101)
    mtn = ValueNoise(202)
    rock = ValueNoise(303)
    faces = {}
    N = ENV_N
    for face in ('px', 'nx', 'py', 'ny', 'pz', 'nz'):
        buf = bytearray(N * N * 3)
        for j in range(N):
            tc = 2.0 * (j + 0.5) / N - 1.0
            for i in range(N):
                sc = 2.0 * (i + 0.5) / N - 1.0
                d = v_norm(face_dir(face, sc, tc))
                c = sky_color(d, cloud, mtn, rock)
                o = (j * N + i) * 3
                buf[o] = int(clamp(round(c[0]), 0, 255))
                buf[o + 1] = int(clamp(round(c[1]), 0, 255))
                buf[o + 2] = int(clamp(round(c[2]), 0, 255))
        faces[face] = bytes(buf)
    return faces


# ---------------------------------------------------------------------------
# temple
# ---------------------------------------------------------------------------

STYLO_TOP = 1.5
COL_H = 10.3
COL_TOP = STYLO_TOP + COL_H          # 11.8
ARCH_TOP = COL_TOP + 1.3             # 13.1 architrave
FRIEZE_TOP = ARCH_TOP + 1.3          # 14.4
CORNICE_TOP = FRIEZE_TOP + 0.4       # 14.8
RIDGE_Y = CORNICE_TOP + 4.0          # 18.8
PX, PZ = 13.5, 32.0                  # peristyle column centre lines


def column_mesh():
    m = Mesh()
    # base (plinth), echinus, abacus as boxes
    m.box((-1.05, 0.0, -1.05), (1.05, 0.3, 1.05), tile=1.0)
    m.box((-0.98, 9.5, -0.98), (0.98, 9.9, 0.98), tile=1.0)
    m.box((-1.1, 9.9, -1.1), (1.1, 10.3, 1.1), tile=1.0)
    # fluted, tapered shaft with entasis (20 flutes, 4 facets each, 10 height bands)
    flutes, sub, bands = 20, 4, 10
    y0, y1 = 0.3, 9.5
    r0, r1 = 0.95, 0.76
    depth = 0.06

    def radius(yy):
        s = (yy - y0) / (y1 - y0)
        return lerp(r0, r1, s) + 0.025 * math.sin(math.pi * s)

    def dradius(yy):
        s = (yy - y0) / (y1 - y0)
        return ((r1 - r0) + 0.025 * math.pi * math.cos(math.pi * s)) / (y1 - y0)

    rings = []
    for bi in range(bands + 1):
        yy = y0 + (y1 - y0) * bi / bands
        R = radius(yy)
        dR = dradius(yy)
        ring = []
        for f in range(flutes):
            for k in range(sub + 1):
                t = k / sub
                th = 2 * math.pi * (f + t) / flutes
                prof = 1.0 - depth * math.sin(math.pi * t)
                r = R * prof
                r_th = -R * depth * math.pi * math.cos(math.pi * t) * flutes / (2 * math.pi)
                r_y = dR * prof
                ct, st = math.cos(th), math.sin(th)
                p = (r * ct, yy, r * st)
                d_th = (r_th * ct - r * st, 0.0, r_th * st + r * ct)
                d_y = (r_y * ct, 1.0, r_y * st)
                n = v_norm(v_cross(d_th, d_y))
                if v_dot(n, (ct, 0.0, st)) < 0:
                    n = v_mul(n, -1.0)
                uv = ((f + t) / flutes * 2.0, (y1 - yy) / 3.0)
                ring.append(m.vert(p, n, uv))
        rings.append(ring)
    per = flutes * (sub + 1)
    for bi in range(bands):
        ra, rb = rings[bi], rings[bi + 1]
        for f in range(flutes):
            for k in range(sub):
                i0 = f * (sub + 1) + k
                a, b_, c, d = ra[i0], ra[i0 + 1], rb[i0 + 1], rb[i0]
                ref = v_add(m.nrm[a], m.nrm[c])
                m.tri_oriented(a, b_, c, ref)
                m.tri_oriented(a, c, d, ref)
    assert per == len(rings[0])
    return m


def column_positions():
    cols = []
    xs = [-PX + i * (2 * PX) / 7 for i in range(8)]
    for z in (PZ, -PZ):
        for x in xs:
            cols.append(('peristyle', x, z))
    for x in (PX, -PX):
        for j in range(1, 16):
            cols.append(('peristyle', x, -PZ + j * 4.0))
    for z in (27.5, -27.5):
        for i in range(6):
            cols.append(('prostyle', -9.5 + i * 3.8, z))
    for x in (5.5, -5.5):
        for j in range(8):
            cols.append(('interior', x, -4.0 + j * 3.5))
    return cols


def ring_beam(m, y0, y1, half_w, tile=2.0):
    """Rectangular ring of 4 non-overlapping beams on the peristyle centre lines."""
    m.box((-PX - half_w, y0, PZ - half_w), (PX + half_w, y1, PZ + half_w), tile)
    m.box((-PX - half_w, y0, -PZ - half_w), (PX + half_w, y1, -PZ + half_w), tile)
    m.box((PX - half_w, y0, -PZ + half_w), (PX + half_w, y1, PZ - half_w), tile)
    m.box((-PX - half_w, y0, -PZ + half_w), (-PX + half_w, y1, PZ - half_w), tile)


def wall_with_door(m, z, x0, x1, y0, y1, door_w, door_h, thick=1.0):
    z0, z1 = z - thick / 2, z + thick / 2
    m.box((x0, y0, z0), (-door_w / 2, y1, z1))
    m.box((door_w / 2, y0, z0), (x1, y1, z1))
    m.box((-door_w / 2, y0 + door_h, z0), (door_w / 2, y1, z1))


def prism_x(m, x_half, y_base, y_apex, z0, z1, tile=2.0):
    """Triangular (pediment) prism: triangle in XY, extruded along Z."""
    A = (-x_half, y_base)
    B = (x_half, y_base)
    C = (0.0, y_apex)
    for zz, nz in ((z1, 1.0), (z0, -1.0)):
        n = (0.0, 0.0, nz)
        ia = m.vert((A[0], A[1], zz), n, (0.0, 0.0))
        ib = m.vert((B[0], B[1], zz), n, (2 * x_half / tile, 0.0))
        ic = m.vert((C[0], C[1], zz), n, (x_half / tile, (y_apex - y_base) / tile))
        m.tri_oriented(ia, ib, ic, n)
    for P, Q in ((A, B), (B, C), (C, A)):
        e = (Q[0] - P[0], Q[1] - P[1])
        n = v_norm((e[1], -e[0], 0.0))
        # make it point away from the triangle centroid
        cen = (0.0, (2 * y_base + y_apex) / 3.0)
        mid = ((P[0] + Q[0]) / 2 - cen[0], (P[1] + Q[1]) / 2 - cen[1])
        if n[0] * mid[0] + n[1] * mid[1] < 0:
            n = v_mul(n, -1.0)
        L = math.hypot(*e) / tile
        W = (z1 - z0) / tile
        m.quad([(P[0], P[1], z0), (Q[0], Q[1], z0), (Q[0], Q[1], z1), (P[0], P[1], z1)], n,
               [(0.0, 0.0), (L, 0.0), (L, W), (0.0, W)])


def sloped_box(m, side, s0, s1, z0, z1, lift, thick, tile=2.0):
    """A box lying on the roof slope of side +1/-1, from fraction s0..s1 of the
    way eave->ridge, spanning z0..z1, raised `lift` above the slope plane."""
    eave = (side * (PX + 1.3 + 0.4), CORNICE_TOP)
    ridge = (0.0, RIDGE_Y)
    d = (ridge[0] - eave[0], ridge[1] - eave[1])
    L = math.hypot(*d)
    dirv = (d[0] / L, d[1] / L, 0.0)
    up = (-dirv[1], dirv[0], 0.0)      # perpendicular to the slope, in the XY plane
    if up[1] < 0:
        up = v_mul(up, -1.0)
    sm = (s0 + s1) / 2
    base = (eave[0] + d[0] * sm, eave[1] + d[1] * sm, (z0 + z1) / 2)
    c = v_add(base, v_mul(up, lift + thick / 2))
    ax = v_mul(dirv, (s1 - s0) * L / 2)
    ay = v_mul(up, thick / 2)
    az = (0.0, 0.0, (z1 - z0) / 2)
    m.box_axes(c, ax, ay, az, tile)


def build_temple():
    b = GltfBuilder()
    stats = {}
    # --- materials -------------------------------------------------------
    albedo, normal = ground_textures()
    img_albedo = b.image_png(encode_png(TEX, TEX, 3, albedo), 'ground_albedo')
    img_normal = b.image_png(encode_png(TEX, TEX, 3, normal), 'ground_normal')
    samp = b.add('samplers', {'magFilter': 9729, 'minFilter': 9987, 'wrapS': 10497, 'wrapT': 10497})
    tex_albedo = b.add('textures', {'sampler': samp, 'source': img_albedo, 'name': 'ground_albedo'})
    tex_normal = b.add('textures', {'sampler': samp, 'source': img_normal, 'name': 'ground_normal'})
    mat_ground = b.add('materials', {
        'name': 'ground_paving',
        'pbrMetallicRoughness': {'baseColorFactor': [1.0, 1.0, 1.0, 1.0],
                                 'baseColorTexture': {'index': tex_albedo},
                                 'metallicFactor': 0.0, 'roughnessFactor': 0.85},
        'normalTexture': {'index': tex_normal, 'scale': 1.0}})
    mat_marble = b.add('materials', {
        'name': 'marble',
        'pbrMetallicRoughness': {'baseColorFactor': [0.91, 0.88, 0.81, 1.0],
                                 'metallicFactor': 0.0, 'roughnessFactor': 0.55}})
    mat_weathered = b.add('materials', {
        'name': 'marble_weathered',
        'pbrMetallicRoughness': {'baseColorFactor': [0.80, 0.75, 0.66, 1.0],
                                 'metallicFactor': 0.0, 'roughnessFactor': 0.7}})
    mat_roof = b.add('materials', {
        'name': 'roof_terracotta',
        'pbrMetallicRoughness': {'baseColorFactor': [0.62, 0.30, 0.20, 1.0],
                                 'metallicFactor': 0.0, 'roughnessFactor': 0.8}})
    mat_wood = b.add('materials', {
        'name': 'timber',
        'pbrMetallicRoughness': {'baseColorFactor': [0.36, 0.25, 0.16, 1.0],
                                 'metallicFactor': 0.0, 'roughnessFactor': 0.9}})

    meshes = {}

    def add_mesh(name, parts):
        prims = [emit_primitive(b, mm, mat) for mm, mat in parts]
        meshes[name] = sum(mm.tri_count() for mm, _ in parts)
        return b.add('meshes', {'name': name, 'primitives': prims})

    # --- ground: 300 m x 300 m, 30 x 30 quads ----------------------------
    g = Mesh()
    G, GN = 150.0, 30
    for j in range(GN + 1):
        for i in range(GN + 1):
            x = -G + 2 * G * i / GN
            z = -G + 2 * G * j / GN
            g.vert((x, 0.0, z), (0.0, 1.0, 0.0), (x / GROUND_TILE_M, z / GROUND_TILE_M),
                   (1.0, 0.0, 0.0, 1.0))
    for j in range(GN):
        for i in range(GN):
            a = j * (GN + 1) + i
            g.tri_oriented(a, a + 1, a + GN + 2, (0, 1, 0))
            g.tri_oriented(a, a + GN + 2, a + GN + 1, (0, 1, 0))
    mesh_ground = add_mesh('ground', [(g, mat_ground)])

    # --- stylobate: 3 steps ---------------------------------------------
    s = Mesh()
    for k in range(3):
        hx = 15.4 + (2 - k) * 0.8
        hz = 34.0 + (2 - k) * 0.8
        ylo = -0.2 if k == 0 else 0.5 * k
        s.box((-hx, ylo, -hz), (hx, 0.5 * (k + 1), hz))
    mesh_stylobate = add_mesh('stylobate', [(s, mat_marble)])

    # --- column ----------------------------------------------------------
    col = column_mesh()
    mesh_column = add_mesh('column', [(col, mat_marble)])

    # --- cella walls -------------------------------------------------------
    c = Mesh()
    c.box((-9.5, STYLO_TOP, -24.0), (-8.5, ARCH_TOP, 24.0))
    c.box((8.5, STYLO_TOP, -24.0), (9.5, ARCH_TOP, 24.0))
    wall_with_door(c, 23.5, -8.5, 8.5, STYLO_TOP, ARCH_TOP, 4.4, 8.0)
    wall_with_door(c, -23.5, -8.5, 8.5, STYLO_TOP, ARCH_TOP, 4.4, 8.0)
    wall_with_door(c, -8.0, -8.5, 8.5, STYLO_TOP, ARCH_TOP, 3.2, 7.0)
    mesh_cella = add_mesh('cella', [(c, mat_marble)])

    # --- entablature: architrave, frieze + triglyphs, cornice, inner beams --
    e = Mesh()
    ring_beam(e, COL_TOP, ARCH_TOP, 1.0)
    ring_beam(e, ARCH_TOP, FRIEZE_TOP, 0.9)
    ring_beam(e, FRIEZE_TOP, CORNICE_TOP, 1.3 + 0.4)
    for z in (27.5, -27.5):
        e.box((-10.6, COL_TOP, z - 1.0), (10.6, ARCH_TOP, z + 1.0))
        e.box((-10.6, ARCH_TOP, z - 0.9), (10.6, FRIEZE_TOP, z + 0.9))
    for x in (5.5, -5.5):
        e.box((x - 0.9, COL_TOP, -5.0), (x + 0.9, ARCH_TOP, 21.5))
    # triglyphs on the outer frieze faces
    fo = 0.9
    tg = 0.12
    nx = 14
    for i in range(nx + 1):
        x = -PX + i * (2 * PX) / nx
        for z, sgn in ((PZ + fo, 1), (-PZ - fo, -1)):
            zz = (z, z + sgn * tg)
            e.box((x - 0.4, ARCH_TOP + 0.05, min(zz)), (x + 0.4, FRIEZE_TOP - 0.05, max(zz)), tile=1.0)
    for j in range(1, 32):
        z = -PZ + j * 2.0
        for x, sgn in ((PX + fo, 1), (-PX - fo, -1)):
            xx = (x, x + sgn * tg)
            e.box((min(xx), ARCH_TOP + 0.05, z - 0.4), (max(xx), FRIEZE_TOP - 0.05, z + 0.4), tile=1.0)
    # pediments (tympanum) front and back
    ped = Mesh()
    prism_x(ped, PX + 0.9, CORNICE_TOP, RIDGE_Y - 0.35, PZ - 0.4, PZ + 0.6)
    prism_x(ped, PX + 0.9, CORNICE_TOP, RIDGE_Y - 0.35, -PZ - 0.6, -PZ + 0.4)
    mesh_entab = add_mesh('entablature', [(e, mat_weathered), (ped, mat_weathered)])

    # --- roof: tiled slabs over the front two thirds, exposed timber rafters
    #     and purlins over the rear third (partially collapsed roof) ---------
    rz_front = PZ + 1.7 + 0.4
    rz_cut = -8.0
    r = Mesh()
    for side in (1, -1):
        sloped_box(r, side, 0.0, 1.0, rz_cut, rz_front, 0.0, 0.3)
    w = Mesh()
    # ridge beam over the full length
    w.box((-0.25, RIDGE_Y - 0.1, -rz_front), (0.25, RIDGE_Y + 0.35, rz_front), tile=1.0)
    for side in (1, -1):
        # rafters every 2.5 m along the exposed part
        zz = rz_cut - 1.25
        while zz > -rz_front + 0.3:
            sloped_box(w, side, 0.02, 0.98, zz - 0.15, zz + 0.15, -0.05, 0.35, tile=1.0)
            zz -= 2.5
        # purlins along z
        for frac in (0.25, 0.5, 0.75):
            sloped_box(w, side, frac - 0.015, frac + 0.015, -rz_front + 0.2, rz_cut, 0.3, 0.25, tile=1.0)
    # a few surviving ceiling beams across the cella (x direction)
    zz = -10.0
    while zz > -31.0:
        w.box((-13.5, CORNICE_TOP - 0.5, zz - 0.2), (13.5, CORNICE_TOP - 0.1, zz + 0.2), tile=1.0)
        zz -= 3.0
    mesh_roof = add_mesh('roof', [(r, mat_roof), (w, mat_wood)])

    # --- nodes ----------------------------------------------------------
    n_ground = b.add('nodes', {'name': 'ground', 'mesh': mesh_ground})
    n_stylo = b.add('nodes', {'name': 'stylobate', 'mesh': mesh_stylobate})
    col_nodes = []
    counts = {}
    for kind, x, z in column_positions():
        counts[kind] = counts.get(kind, 0) + 1
        name = 'column_%s_%02d' % (kind, counts[kind] - 1)
        col_nodes.append(b.add('nodes', {'name': name, 'mesh': mesh_column,
                                         'translation': [r6(x), STYLO_TOP, r6(z)]}))
    n_cols = b.add('nodes', {'name': 'columns', 'children': col_nodes})
    n_cella = b.add('nodes', {'name': 'cella', 'mesh': mesh_cella})
    n_entab = b.add('nodes', {'name': 'entablature', 'mesh': mesh_entab})
    n_roof = b.add('nodes', {'name': 'roof', 'mesh': mesh_roof})
    n_temple = b.add('nodes', {'name': 'temple',
                               'children': [n_ground, n_stylo, n_cols, n_cella, n_entab, n_roof]})
    cam = b.add('cameras', {'name': 'overview', 'type': 'perspective',
                            'perspective': {'yfov': 0.9, 'aspectRatio': 1.7777778,
                                            'znear': 0.1, 'zfar': 1000.0}})
    eye = (30.0, 6.0, 62.0)
    target = (0.0, 7.0, 8.0)
    q = look_at_quat(eye, target)
    n_cam = b.add('nodes', {'name': 'camera', 'camera': cam,
                            'translation': list(eye), 'rotation': [r6(c) for c in q]})
    b.add('scenes', {'name': 'temple', 'nodes': [n_temple, n_cam]})

    # --- stats ----------------------------------------------------------
    ncol = len(col_nodes)
    total = (meshes['ground'] + meshes['stylobate'] + ncol * meshes['column'] + meshes['cella'] +
             meshes['entablature'] + meshes['roof'])
    stats['mesh_tris'] = dict(meshes)
    stats['columns'] = ncol
    stats['column_counts'] = counts
    stats['total_tris'] = total
    stats['unique_tris'] = sum(meshes.values())
    stats['camera'] = {'eye': eye, 'target': target, 'rotation': [r6(c) for c in q]}
    # bounds of the temple structure (excluding the 300 m ground)
    lo = [1e9] * 3
    hi = [-1e9] * 3
    for mm in (s, c, e, ped, r, w):
        for p in mm.pos:
            for i in range(3):
                lo[i] = min(lo[i], p[i])
                hi[i] = max(hi[i], p[i])
    stats['bounds'] = (lo, hi)
    return b.to_glb(), stats


# ---------------------------------------------------------------------------
# character
# ---------------------------------------------------------------------------

JOINTS = [
    # name, parent, global bind position
    ('hips', None, (0.0, 0.95, 0.0)),
    ('spine', 'hips', (0.0, 1.05, 0.0)),
    ('chest', 'spine', (0.0, 1.25, 0.0)),
    ('neck', 'chest', (0.0, 1.46, 0.0)),
    ('head', 'neck', (0.0, 1.56, 0.0)),
    ('upperarm_L', 'chest', (0.20, 1.42, 0.0)),
    ('forearm_L', 'upperarm_L', (0.20, 1.14, 0.0)),
    ('upperarm_R', 'chest', (-0.20, 1.42, 0.0)),
    ('forearm_R', 'upperarm_R', (-0.20, 1.14, 0.0)),
    ('thigh_L', 'hips', (0.10, 0.92, 0.0)),
    ('shin_L', 'thigh_L', (0.10, 0.50, 0.0)),
    ('foot_L', 'shin_L', (0.10, 0.08, 0.0)),
    ('thigh_R', 'hips', (-0.10, 0.92, 0.0)),
    ('shin_R', 'thigh_R', (-0.10, 0.50, 0.0)),
    ('foot_R', 'shin_R', (-0.10, 0.08, 0.0)),
]
JI = {name: i for i, (name, _, _) in enumerate(JOINTS)}


def catmull(points, samples):
    """Resample a list of (t, r) control points with a Catmull-Rom spline (by index)."""
    out = []
    n = len(points)
    for s in range(samples + 1):
        u = s / samples * (n - 1)
        i = min(int(u), n - 2)
        f = u - i
        p0 = points[max(i - 1, 0)]
        p1 = points[i]
        p2 = points[i + 1]
        p3 = points[min(i + 2, n - 1)]
        vals = []
        for k in range(2):
            a, b_, c, d = p0[k], p1[k], p2[k], p3[k]
            vals.append(0.5 * ((2 * b_) + (-a + c) * f + (2 * a - 5 * b_ + 4 * c - d) * f * f +
                               (-a + 3 * b_ - 3 * c + d) * f * f * f))
        out.append(vals)
    out[0][1] = 0.0
    out[-1][1] = 0.0
    return out


def chain_weights(t, joints, bounds, blend):
    """Piecewise weights along a chain: joints[i] owns (bounds[i-1], bounds[i]);
    linear-smooth transitions of half-width `blend` around each bound."""
    w = {}
    # find the segment
    for bi, bd in enumerate(bounds):
        if t < bd - blend:
            w[joints[bi]] = 1.0
            return w
        if t <= bd + blend:
            s = smoothstep(bd - blend, bd + blend, t)
            if 1 - s > 0:
                w[joints[bi]] = 1 - s
            if s > 0:
                w[joints[bi + 1]] = s
            return w
    w[joints[-1]] = 1.0
    return w


def lathe(mesh, origin, axis, side1, side2, profile, segs, weight_fn, s1=1.0, s2=1.0,
          clamp_y=None):
    """Surface of revolution (possibly elliptical).  profile: [(t, r)] with r=0
    at both ends (poles).  Smooth normals are computed by area-weighted face
    normal averaging across the seam."""
    base = len(mesh.pos)
    canon = []       # canonical vertex id for normal accumulation
    ring_ids = []
    pts = []
    for ri, (t, r) in enumerate(profile):
        c = v_add(origin, v_mul(axis, t))
        ids = []
        if ri == 0 or ri == len(profile) - 1:
            p = c
            if clamp_y is not None and p[1] < clamp_y:
                p = (p[0], clamp_y, p[2])
            idx = len(mesh.pos)
            mesh.vert(p, (0.0, 0.0, 0.0), (0.5, 1.0 - ri / (len(profile) - 1)))
            canon.append(idx)
            pts.append(t)
            ids = [idx]
        else:
            for k in range(segs + 1):
                a = 2 * math.pi * (k % segs) / segs
                off = v_add(v_mul(side1, math.cos(a) * r * s1), v_mul(side2, math.sin(a) * r * s2))
                p = v_add(c, off)
                if clamp_y is not None and p[1] < clamp_y:
                    p = (p[0], clamp_y, p[2])
                idx = len(mesh.pos)
                mesh.vert(p, (0.0, 0.0, 0.0), (k / segs, 1.0 - ri / (len(profile) - 1)))
                canon.append(idx if k < segs else idx - segs)
                pts.append(t)
                ids.append(idx)
        ring_ids.append(ids)
    tris = []
    nr = len(profile)
    for ri in range(nr - 1):
        A = ring_ids[ri]
        B = ring_ids[ri + 1]
        if len(A) == 1:
            for k in range(segs):
                tris.append((A[0], B[k + 1], B[k]))
        elif len(B) == 1:
            for k in range(segs):
                tris.append((A[k], A[k + 1], B[0]))
        else:
            for k in range(segs):
                tris.append((A[k], A[k + 1], B[k + 1]))
                tris.append((A[k], B[k + 1], B[k]))
    # consistent orientation: make the signed volume positive
    vol = 0.0
    for a, b_, c in tris:
        vol += v_dot(mesh.pos[a], v_cross(mesh.pos[b_], mesh.pos[c]))
    if vol < 0:
        tris = [(a, c, b_) for a, b_, c in tris]
    acc = {}
    for a, b_, c in tris:
        fn = v_cross(v_sub(mesh.pos[b_], mesh.pos[a]), v_sub(mesh.pos[c], mesh.pos[a]))
        for v in (a, b_, c):
            cv = canon[v - base]
            o = acc.get(cv, (0.0, 0.0, 0.0))
            acc[cv] = v_add(o, fn)
    for v in range(base, len(mesh.pos)):
        n = acc[canon[v - base]]
        mesh.nrm[v] = v_norm(n)
    for a, b_, c in tris:
        fn = v_cross(v_sub(mesh.pos[b_], mesh.pos[a]), v_sub(mesh.pos[c], mesh.pos[a]))
        if v_len(fn) > 1e-14:
            mesh.idx += (a, b_, c)
    for v in range(base, len(mesh.pos)):
        mesh.weights.append(weight_fn(mesh.pos[v], pts[v - base]))


def pack_weights(mesh):
    joints = []
    weights = []
    for w in mesh.weights:
        items = sorted(((wt, j) for j, wt in w.items() if wt > 1e-6), key=lambda t: (-t[0], t[1]))[:4]
        tot = sum(wt for wt, _ in items)
        items = [(wt / tot, j) for wt, j in items]
        js = [j for _, j in items] + [0] * (4 - len(items))
        ws = [f32(wt) for wt, _ in items]
        # make the float32 sum exactly 1 by adjusting the largest weight
        if len(ws) > 1:
            ws[0] = f32(1.0 - sum(ws[1:]))
        else:
            ws = [1.0]
        ws += [0.0] * (4 - len(ws))
        joints.append(js)
        weights.append(ws)
    mesh.joints = joints
    mesh.weights = weights


def build_character():
    b = GltfBuilder()
    mats = {}
    for name, col in (('skin', (0.87, 0.66, 0.54)), ('top', (0.16, 0.36, 0.66)),
                      ('pants', (0.18, 0.18, 0.24)), ('shoes', (0.80, 0.20, 0.15))):
        mats[name] = b.add('materials', {
            'name': name,
            'pbrMetallicRoughness': {'baseColorFactor': [col[0], col[1], col[2], 1.0],
                                     'metallicFactor': 0.0, 'roughnessFactor': 0.7}})
    X, Y, Z = (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)
    DOWN = (0.0, -1.0, 0.0)

    # --- torso ---------------------------------------------------------
    torso = Mesh()
    tprof = [(0.78, 0.0), (0.80, 0.09), (0.84, 0.145), (0.90, 0.165), (0.96, 0.165),
             (1.03, 0.152), (1.09, 0.140), (1.16, 0.150), (1.23, 0.166), (1.31, 0.176),
             (1.38, 0.180), (1.43, 0.168), (1.47, 0.135), (1.50, 0.075), (1.51, 0.0)]
    prof = catmull(tprof, 36)

    def w_torso(p, t):
        return chain_weights(p[1], [JI['hips'], JI['spine'], JI['chest']], [1.02, 1.20], 0.06)

    # lathe along +Y: side1 = Z (front/back, flattened), side2 = X (width)
    lathe(torso, (0.0, 0.0, 0.0), Y, Z, X, prof, 24, w_torso, s1=0.62, s2=1.0)

    # --- head + neck (skin) --------------------------------------------
    skin = Mesh()
    hprof = [(-1.0, 0.0)]
    for i in range(1, 16):
        a = math.pi * i / 16
        hprof.append((-math.cos(a), math.sin(a)))
    hprof.append((1.0, 0.0))

    def w_head(p, t):
        return chain_weights(p[1], [JI['neck'], JI['head']], [1.555], 0.03)

    hc = (0.0, 1.62, 0.012)
    lathe(skin, hc, Y, Z, X, [(t * 0.116, r) for t, r in hprof], 24, w_head,
          s1=0.105, s2=0.09)

    nprof = catmull([(1.38, 0.0), (1.40, 0.045), (1.48, 0.047), (1.56, 0.046), (1.60, 0.0)], 10)

    def w_neck(p, t):
        return chain_weights(p[1], [JI['chest'], JI['neck'], JI['head']], [1.45, 1.555], 0.03)

    lathe(skin, (0.0, 0.0, 0.0), Y, Z, X, nprof, 16, w_neck)

    # --- arms (skin) ------------------------------------------------------
    aprof = catmull([(0.0, 0.0), (0.015, 0.045), (0.05, 0.052), (0.15, 0.048), (0.26, 0.042),
                     (0.30, 0.041), (0.40, 0.038), (0.52, 0.032), (0.56, 0.034), (0.60, 0.042),
                     (0.66, 0.040), (0.71, 0.025), (0.725, 0.0)], 34)
    for side, sx in (('L', 1.0), ('R', -1.0)):
        top = (0.20 * sx, 1.47, 0.0)

        def w_arm(p, t, side=side):
            return _rev_chain(p[1], [JI['chest'], JI['upperarm_' + side], JI['forearm_' + side]],
                              [1.405, 1.14], [0.035, 0.05])

        lathe(skin, top, DOWN, Z, X, aprof, 16, w_arm, s1=1.0, s2=0.9)

    # --- legs (pants) -------------------------------------------------
    pants = Mesh()
    lprof = catmull([(0.0, 0.0), (0.02, 0.06), (0.06, 0.085), (0.15, 0.082), (0.30, 0.068),
                     (0.45, 0.055), (0.50, 0.051), (0.55, 0.053), (0.65, 0.052), (0.80, 0.040),
                     (0.90, 0.034), (0.94, 0.030), (0.96, 0.0)], 36)
    for side, sx in (('L', 1.0), ('R', -1.0)):
        top = (0.10 * sx, 1.0, 0.0)

        def w_leg(p, t, side=side):
            return _rev_chain(p[1], [JI['hips'], JI['thigh_' + side], JI['shin_' + side],
                                     JI['foot_' + side]], [0.90, 0.50, 0.09], [0.04, 0.05, 0.025])

        lathe(pants, top, DOWN, Z, X, lprof, 20, w_leg)

    # --- feet (shoes) ---------------------------------------------------
    shoes = Mesh()
    fprof = catmull([(-0.06, 0.0), (-0.05, 0.035), (-0.02, 0.046), (0.05, 0.046), (0.12, 0.050),
                     (0.17, 0.040), (0.20, 0.022), (0.207, 0.0)], 14)
    for side, sx in (('L', 1.0), ('R', -1.0)):
        def w_foot(p, t, side=side):
            return {JI['foot_' + side]: 1.0}

        lathe(shoes, (0.10 * sx, 0.047, 0.0), Z, Y, X, fprof, 16, w_foot, s1=1.0, s2=1.0,
              clamp_y=0.0)

    parts = [(torso, 'top'), (skin, 'skin'), (pants, 'pants'), (shoes, 'shoes')]
    prims = []
    tri_counts = {}
    lo = [1e9] * 3
    hi = [-1e9] * 3
    for mm, mname in parts:
        pack_weights(mm)
        prims.append(emit_primitive(b, mm, mats[mname], skinned=True))
        tri_counts[mname] = mm.tri_count()
        for p in mm.pos:
            for i in range(3):
                lo[i] = min(lo[i], p[i])
                hi[i] = max(hi[i], p[i])
    mesh = b.add('meshes', {'name': 'heroine', 'primitives': prims})

    # --- skeleton nodes ------------------------------------------------
    # node 0: skinned mesh (scene root, no transform), node 1: "heroine" placement root,
    # nodes 2..: joints in JOINTS order
    n_body = b.add('nodes', {'name': 'heroine_body', 'mesh': mesh, 'skin': 0})
    n_root = b.add('nodes', {'name': 'heroine', 'children': []})
    jnode = {}
    for name, parent, gp in JOINTS:
        pp = (0.0, 0.0, 0.0) if parent is None else dict((n, g) for n, _, g in JOINTS)[parent]
        t = v_sub(gp, pp)
        jnode[name] = b.add('nodes', {'name': name, 'translation': [r6(t[0]), r6(t[1]), r6(t[2])]})
    for name, parent, _ in JOINTS:
        if parent is None:
            b.doc['nodes'][n_root]['children'].append(jnode[name])
        else:
            b.doc['nodes'][jnode[parent]].setdefault('children', []).append(jnode[name])
    ibm = []
    for name, parent, gp in JOINTS:
        ibm += [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -gp[0], -gp[1], -gp[2], 1]
    ibm_acc = b.accessor(ibm, FLOAT, 'MAT4', name='inverseBindMatrices')
    b.add('skins', {'name': 'heroine_skin', 'joints': [jnode[n] for n, _, _ in JOINTS],
                    'skeleton': jnode['hips'], 'inverseBindMatrices': ibm_acc})

    # --- run animation ---------------------------------------------------
    T = 0.7
    K = 29                    # keyframes (last == first, for seamless looping)
    times = [T * i / (K - 1) for i in range(K)]
    t_acc = b.accessor(times, FLOAT, 'SCALAR', minmax=True, name='run_time')
    qx = lambda a: quat_axis_angle(X, a)
    qy = lambda a: quat_axis_angle(Y, a)
    qz = lambda a: quat_axis_angle(Z, a)

    def pose(ph):
        """Local joint rotations for cycle phase ph (radians)."""
        rot = {}
        hip_t = (0.0, 0.925 - 0.025 * math.cos(2 * ph), 0.0)
        rot['hips'] = quat_mul(qy(-0.15 * math.sin(ph)), qz(0.04 * math.cos(ph)))
        rot['spine'] = qx(0.14)
        rot['chest'] = quat_mul(qy(0.25 * math.sin(ph)), qx(0.05))
        rot['neck'] = quat_mul(qy(-0.10 * math.sin(ph)), qx(-0.10))
        rot['head'] = qx(-0.08)
        for side, off, abd in (('L', 0.0, 0.10), ('R', math.pi, -0.10)):
            p = ph + off
            rot['thigh_' + side] = qx(-0.15 - 0.65 * math.sin(p))
            rot['shin_' + side] = qx(0.2 + 1.2 * ((1 + math.cos(p + 0.3)) / 2) ** 2)
            rot['foot_' + side] = qx(-0.30 * math.sin(p))
            rot['upperarm_' + side] = quat_mul(qz(abd), qx(0.55 * math.sin(p)))
            rot['forearm_' + side] = qx(-1.35 + 0.25 * math.sin(p))
        return hip_t, rot

    samples = {name: [] for name, _, _ in JOINTS}
    hip_ts = []
    for t in times:
        ph = 2 * math.pi * t / T
        ht, rot = pose(ph)
        hip_ts += ht
        for name in samples:
            q = quat_normalize(rot[name])
            prev = samples[name][-1] if samples[name] else None
            if prev is not None and sum(a * c for a, c in zip(prev, q)) < 0:
                q = tuple(-c for c in q)
            samples[name].append(q)
    channels = []
    samplers = []
    out = b.accessor(hip_ts, FLOAT, 'VEC3', name='run_hips_translation')
    samplers.append({'input': t_acc, 'output': out, 'interpolation': 'LINEAR'})
    channels.append({'sampler': 0, 'target': {'node': jnode['hips'], 'path': 'translation'}})
    for name, _, _ in JOINTS:
        vals = [f32(c) for q in samples[name] for c in q]
        out = b.accessor(vals, FLOAT, 'VEC4', name='run_%s_rotation' % name)
        samplers.append({'input': t_acc, 'output': out, 'interpolation': 'LINEAR'})
        channels.append({'sampler': len(samplers) - 1,
                         'target': {'node': jnode[name], 'path': 'rotation'}})
    b.add('animations', {'name': 'run', 'samplers': samplers, 'channels': channels})
    b.add('scenes', {'name': 'heroine', 'nodes': [n_body, n_root]})
    stats = {'tris': tri_counts, 'total_tris': sum(tri_counts.values()),
             'verts': sum(len(mm.pos) for mm, _ in parts),
             'bounds': (lo, hi), 'duration': T, 'keys': K,
             'joints': [n for n, _, _ in JOINTS]}
    return b.to_glb(), stats


def _rev_chain(y, joints, bounds, blends):
    """Chain along decreasing y: joints[0] above bounds[0], joints[1] between
    bounds[0] and bounds[1], ...  Each bound has its own blend half-width."""
    for i, (bd, bl) in enumerate(zip(bounds, blends)):
        if y > bd + bl:
            return {joints[i]: 1.0}
        if y >= bd - bl:
            s = smoothstep(bd + bl, bd - bl, y)   # 0 above, 1 below
            w = {}
            if 1 - s > 0:
                w[joints[i]] = 1 - s
            if s > 0:
                w[joints[i + 1]] = w.get(joints[i + 1], 0.0) + s
            return w
    return {joints[-1]: 1.0}


# ---------------------------------------------------------------------------
# documentation files
# ---------------------------------------------------------------------------


def fmt_v(v):
    return '(%s)' % ', '.join('%.2f' % c for c in v)


def write_docs(root, tstats, cstats, sizes):
    lo, hi = tstats['bounds']
    clo, chi = cstats['bounds']
    mt = tstats['mesh_tris']
    cc = tstats['column_counts']
    lines = [
        '# rrc test assets',
        '',
        'All files in this directory are generated by `scripts/make_assets.py`',
        '(`/usr/bin/python3 scripts/make_assets.py`; standard library only, deterministic).',
        'Do not edit them by hand; change the generator and re-run it.',
        'Validate the GLBs with `scripts/validate-assets` (Khronos glTF-Validator).',
        '',
        'Conventions: metres, +Y up, right-handed, glTF 2.0 (front of a character = +Z).',
        '',
        '## temple.glb (%d bytes)' % sizes['temple.glb'],
        '',
        'Parthenon-like peripteral temple with a partially collapsed roof, designed for',
        'high depth complexity in fly-throughs.',
        '',
        '* Scene `temple`, root nodes: `temple`, `camera`.',
        '* `temple` children: `ground`, `stylobate`, `columns`, `cella`, `entablature`, `roof`.',
        '* `columns` has %d children, each instancing the shared mesh `column` via its' % tstats['columns'],
        '  translation: `column_peristyle_00..%02d` (%d, 8 x 17 peristyle at x = +-%.1f, z = +-%.1f),'
        % (cc['peristyle'] - 1, cc['peristyle'], PX, PZ),
        '  `column_prostyle_00..%02d` (%d, 6 in front of each porch at z = +-27.5),'
        % (cc['prostyle'] - 1, cc['prostyle']),
        '  `column_interior_00..%02d` (%d, two rows inside the cella at x = +-5.5).'
        % (cc['interior'] - 1, cc['interior']),
        '* Column: plinth box, fluted tapered shaft (20 flutes x 4 facets, 10 bands, entasis),',
        '  echinus + abacus boxes; %.1f m tall, base radius 0.95 m; stands on the stylobate' % COL_H,
        '  top at y = %.1f.' % STYLO_TOP,
        '* Stylobate: 3 steps of 0.5 m (top 30.8 m x 68 m, bottom 34 m x 71.2 m).',
        '* Cella: side walls at x = +-9, end walls at z = +-23.5 with 4.4 m x 8 m doors, a cross',
        '  wall at z = -8 with a 3.2 m x 7 m door; walls reach y = %.1f.' % ARCH_TOP,
        '* Entablature (mesh `entablature`): architrave %.1f..%.1f, frieze with %s' % (COL_TOP, ARCH_TOP, 'triglyphs'),
        '  %.1f..%.1f, cornice to %.1f; inner beams over the porches and interior rows;' % (ARCH_TOP, FRIEZE_TOP, CORNICE_TOP),
        '  pediments (second primitive) front and back up to y = %.2f.' % (RIDGE_Y - 0.35),
        '* Roof (mesh `roof`): terracotta slabs (pitch ~15 deg, ridge y = %.1f) over z = -8..+34.1;' % RIDGE_Y,
        '  over the rear (z < -8) only timber rafters every 2.5 m, purlins, a ridge beam and',
        '  ceiling beams remain (second primitive, material `timber`).',
        '* Ground: 300 m x 300 m plane at y = 0 (30 x 30 quads), UV = xz / %.0f m, material' % GROUND_TILE_M,
        '  `ground_paving` with an embedded 256x256 baseColorTexture (2 m x 1 m slabs in',
        '  running bond) and a matching tangent-space normalTexture; TANGENT = (1,0,0,+1).',
        '  Normal map convention: OpenGL / glTF (+X right, +Y = green = image up, i.e. towards',
        '  decreasing v); bitangent = cross(N, T) * w = -Z for the ground.',
        '  Sampler: REPEAT, LINEAR_MIPMAP_LINEAR / LINEAR.',
        '* Materials: `ground_paving`, `marble`, `marble_weathered`, `roof_terracotta`, `timber`',
        '  (metallic 0; only the ground is textured).',
        '* Camera node `camera` (perspective, yfov 0.9 rad, aspect 16:9, znear 0.1, zfar 1000)',
        '  at %s looking at %s.' % (fmt_v(tstats['camera']['eye']), fmt_v(tstats['camera']['target'])),
        '* Bounding box of the building (excluding the ground): min %s, max %s.' % (fmt_v(lo), fmt_v(hi)),
        '  Ground: x, z in [-150, 150], y = 0.',
        '* Triangles per mesh: ' + ', '.join('%s %d' % (k, v) for k, v in mt.items()) + '.',
        '  Unique (stored) triangles: %d. Rendered triangles for the whole scene' % tstats['unique_tris'],
        '  (column mesh instanced %d times): **%d**.' % (tstats['columns'], tstats['total_tris']),
        '',
        '### Suggested camera paths',
        '',
        '* Fly-through along the colonnade (the north peristyle aisle, between the outer',
        '  columns at x = +13.5 and the cella wall at x = +9.5): eye y = 3.5 m, x = 11.3,',
        '  z from +45 to -45 over ~12 s, looking along -Z (target = eye + (0, -0.1, -10)).',
        '  Columns pass within 1-2 m of the eye: strong parallax and disocclusion.',
        '* Through the doors: eye y = 4 m, x = 0, z from +60 to -45, looking along -Z; passes the',
        '  porch columns, the front door, the interior colonnade, the cross-wall door and',
        '  exits under the exposed rafters.',
        '* Orbit: centre (0, 8, 0), radius 65 m, eye height 12 m, one revolution in ~20 s,',
        '  looking at the centre.',
        '* Dolly: from (30, 6, 62) (the `camera` node) straight towards (0, 7, 8), stopping',
        '  ~6 m before the front columns.',
        '',
        '## character.glb (%d bytes)' % sizes['character.glb'],
        '',
        'Procedural skinned humanoid "heroine", %.2f m tall, feet at y = 0, facing +Z,' % chi[1],
        'character left = +X.',
        '',
        '* Scene `heroine`, root nodes: `heroine_body` (mesh `heroine` + skin `heroine_skin`,',
        '  no transform, as the glTF spec recommends) and `heroine` (placement root; its child is',
        '  the skeleton root `hips`). Move the character by transforming `heroine`.',
        '* Joints (%d, skin order = JOINTS_0 index): %s.' % (len(cstats['joints']), ', '.join('`%s`' % j for j in cstats['joints'])),
        '  Hierarchy: hips > spine > chest > neck > head; chest > upperarm_L > forearm_L;',
        '  chest > upperarm_R > forearm_R; hips > thigh_L > shin_L > foot_L; hips > thigh_R >',
        '  shin_R > foot_R. Bind pose: all joint rotations identity (arms hanging down),',
        '  inverse bind matrices are pure translations.',
        '* Mesh `heroine`: 4 primitives (materials `top` = torso, `skin` = head/neck/arms,',
        '  `pants` = legs, `shoes` = feet), each with POSITION, NORMAL, TEXCOORD_0, JOINTS_0',
        '  (UNSIGNED_BYTE) and WEIGHTS_0 (FLOAT, sum exactly 1 in float32, at most 2 non-zero',
        '  influences, smooth blends across each joint). Unused influence slots have joint 0',
        '  and weight 0.',
        '* Triangles: ' + ', '.join('%s %d' % (k, v) for k, v in cstats['tris'].items()) +
        '; total **%d** (%d vertices).' % (cstats['total_tris'], cstats['verts']),
        '* Bounding box (bind pose): min %s, max %s.' % (fmt_v(clo), fmt_v(chi)),
        '* Animation `run`: duration %.2f s, %d keyframes (t = 0..%.2f, the last equal to the' % (cstats['duration'], cstats['keys'], cstats['duration']),
        '  first, so it loops seamlessly), LINEAR interpolation; rotation channels on all 15',
        '  joints and a translation channel on `hips` (vertical bob, y = 0.90..0.95).',
        '  The cycle runs in place (no root motion).',
        '* Suggested camera: orbit around (0, 1, 0) at radius 3 m, height 1.4 m; or a side',
        '  dolly from (4, 1.2, 0) to (1.5, 1.2, 0) looking at (0, 1, 0).',
        '',
        '## env/ (cube map)',
        '',
        'Procedural sky, %dx%d RGB8 per face; see `env/README.md` for the face convention.' % (ENV_N, ENV_N),
        'Sun direction: %s (angular radius 2 deg).' % fmt_v(SUN_DIR),
        '',
        '## bump.png',
        '',
        '256x256 8-bit grayscale, tileable hammered-metal height map (white = high): jittered',
        'Voronoi dimples (24 x 24 cells, ~10.7 px) with sharp ridges plus 2-px grain.',
        '',
    ]
    with open(os.path.join(root, 'scenes.md'), 'w') as f:
        f.write('\n'.join(lines))
    with open(os.path.join(root, 'LICENSE.md'), 'w') as f:
        f.write('\n'.join([
            '# Asset licence',
            '',
            'Every file in `assets/` (temple.glb, character.glb, env/*.png, bump.png and these',
            'documents) is generated procedurally by `scripts/make_assets.py` from code in this',
            'repository; no third-party content is used.',
            '',
            'The assets are dedicated to the public domain under CC0 1.0 Universal',
            '(https://creativecommons.org/publicdomain/zero/1.0/).',
            '']))
    with open(os.path.join(root, 'env', 'README.md'), 'w') as f:
        f.write('\n'.join([
            '# Sky cube map',
            '',
            'Generated by `scripts/make_assets.py` (CC0). Six %dx%d 8-bit RGB PNG faces:' % (ENV_N, ENV_N),
            '',
            '| file | GL target | face |',
            '|------|-----------|------|',
            '| px.png | GL_TEXTURE_CUBE_MAP_POSITIVE_X | +X |',
            '| nx.png | GL_TEXTURE_CUBE_MAP_NEGATIVE_X | -X |',
            '| py.png | GL_TEXTURE_CUBE_MAP_POSITIVE_Y | +Y (sky, zenith) |',
            '| ny.png | GL_TEXTURE_CUBE_MAP_NEGATIVE_Y | -Y (ground) |',
            '| pz.png | GL_TEXTURE_CUBE_MAP_POSITIVE_Z | +Z |',
            '| nz.png | GL_TEXTURE_CUBE_MAP_NEGATIVE_Z | -Z |',
            '',
            'Orientation is the standard OpenGL one (GL 4.6 spec, table 8.19; same as the',
            'RenderMan / DirectX layout): upload each PNG with `glTexImage2D` row 0 = the PNG\'s',
            'top row, **without** any vertical flip. Pixel (column i, row j) of a face with size N',
            'has s = (i + 0.5) / N, t = (j + 0.5) / N, sc = 2s - 1, tc = 2t - 1 and samples the',
            'direction:',
            '',
            '* +X: ( 1, -tc, -sc)',
            '* -X: (-1, -tc,  sc)',
            '* +Y: ( sc,  1,  tc)',
            '* -Y: ( sc, -1, -tc)',
            '* +Z: ( sc, -tc,  1)',
            '* -Z: (-sc, -tc, -1)',
            '',
            'World is +Y up. Content: sky gradient, a sun disk (2 deg radius) at direction',
            '%s with glow, fBm clouds, a mountain band with strata and snow' % fmt_v(SUN_DIR),
            'on the horizon, and below the horizon a paved ground plane (0.5 m slabs, dark 4 cm',
            'joints, checker tones, stone grain) whose detail fades into haze with distance.',
            '']))


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(here), 'assets')
    os.makedirs(os.path.join(root, 'env'), exist_ok=True)
    sizes = {}

    def write(rel, data):
        with open(os.path.join(root, rel), 'wb') as f:
            f.write(data)
        sizes[rel] = len(data)
        print('wrote %-16s %8d bytes' % (rel, len(data)))

    temple, tstats = build_temple()
    write('temple.glb', temple)
    character, cstats = build_character()
    write('character.glb', character)
    write('bump.png', encode_png(256, 256, 1, bump_map()))
    for face, data in env_faces().items():
        write('env/%s.png' % face, encode_png(ENV_N, ENV_N, 3, data))
    write_docs(root, tstats, cstats, sizes)
    print('temple: %d triangles rendered (%d unique), %d columns' %
          (tstats['total_tris'], tstats['unique_tris'], tstats['columns']))
    print('character: %d triangles, %d joints, clip "run" %.2f s / %d keys' %
          (cstats['total_tris'], len(cstats['joints']), cstats['duration'], cstats['keys']))


if __name__ == '__main__':
    main()
