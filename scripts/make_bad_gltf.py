#!/usr/bin/python3
"""Writes a deterministic corpus of malformed glTF / GLB files for loader and
validator tests.

  tests/data/good_triangle.gltf     valid reference (embedded base64 buffer)
  tests/data/good_triangle.glb      valid reference (GLB, BIN chunk)
  tests/data/bad_gltf/*.gltf|*.glb  one defect each, derived from the triangle
  tests/data/bad_gltf/manifest.json [{"file", "defect", "expect", "format",
                                      "khronos"}]

"expect" is a lowercase substring that a good validator's error message for the
file should contain.  "khronos" lists the error codes the Khronos glTF-Validator
(npm gltf-validator 2.0.0-dev.3.10, run through scripts/validate-gltf.mjs, which
refuses to load resources from outside the asset's directory) reports for the
file (all distinct error-severity codes, in report order), for reference.

Standard library only.  Usage: /usr/bin/python3 scripts/make_bad_gltf.py [OUTDIR]
(OUTDIR defaults to <repo>/tests/data).
"""

import base64
import json
import os
import struct
import sys

# --------------------------------------------------------------------------
# the base scene: one triangle with POSITION, NORMAL, TEXCOORD_0, u16 indices
# --------------------------------------------------------------------------

POSITIONS = [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0]
NORMALS = [0.0, 0.0, 1.0] * 3
UVS = [0.0, 1.0, 1.0, 1.0, 0.0, 0.0]
INDICES = [0, 1, 2]

POS_OFF, NRM_OFF, UV_OFF, IDX_OFF = 0, 36, 72, 96
NAN = struct.unpack('<f', b'\x00\x00\xc0\x7f')[0]
INF = float('inf')


def make_bin(positions=POSITIONS, indices=INDICES):
    data = struct.pack('<9f', *positions) + struct.pack('<9f', *NORMALS) + struct.pack('<6f', *UVS)
    data += struct.pack('<3H', *indices) + b'\x00\x00'
    assert len(data) == 104
    return data


def data_uri(data):
    return 'data:application/octet-stream;base64,' + base64.b64encode(data).decode('ascii')


def base_doc(bin_data=None, glb=False):
    bin_data = make_bin() if bin_data is None else bin_data
    buf = {'byteLength': len(bin_data)}
    if not glb:
        buf['uri'] = data_uri(bin_data)
    return {
        'asset': {'version': '2.0', 'generator': 'rrc scripts/make_bad_gltf.py'},
        'scene': 0,
        'scenes': [{'name': 'triangle', 'nodes': [0]}],
        'nodes': [{'name': 'triangle', 'mesh': 0}],
        'meshes': [{'name': 'triangle', 'primitives': [{
            'attributes': {'POSITION': 0, 'NORMAL': 1, 'TEXCOORD_0': 2},
            'indices': 3, 'material': 0, 'mode': 4}]}],
        'materials': [{'name': 'red', 'pbrMetallicRoughness': {
            'baseColorFactor': [0.8, 0.1, 0.1, 1.0], 'metallicFactor': 0.0, 'roughnessFactor': 0.6}}],
        'buffers': [buf],
        'bufferViews': [
            {'buffer': 0, 'byteOffset': POS_OFF, 'byteLength': 36, 'target': 34962},
            {'buffer': 0, 'byteOffset': NRM_OFF, 'byteLength': 36, 'target': 34962},
            {'buffer': 0, 'byteOffset': UV_OFF, 'byteLength': 24, 'target': 34962},
            {'buffer': 0, 'byteOffset': IDX_OFF, 'byteLength': 6, 'target': 34963},
        ],
        'accessors': [
            {'bufferView': 0, 'componentType': 5126, 'count': 3, 'type': 'VEC3',
             'min': [0.0, 0.0, 0.0], 'max': [1.0, 1.0, 0.0]},
            {'bufferView': 1, 'componentType': 5126, 'count': 3, 'type': 'VEC3'},
            {'bufferView': 2, 'componentType': 5126, 'count': 3, 'type': 'VEC2'},
            {'bufferView': 3, 'componentType': 5123, 'count': 3, 'type': 'SCALAR'},
        ],
    }


def gltf_text(doc):
    return (json.dumps(doc, indent=2) + '\n').encode('utf-8')


def glb_bytes(doc, bin_data, magic=b'glTF', version=2, length=None, bin_chunk_len=None):
    js = json.dumps(doc, separators=(',', ':')).encode('utf-8')
    while len(js) % 4:
        js += b' '
    b = bytes(bin_data)
    while len(b) % 4:
        b += b'\x00'
    total = 12 + 8 + len(js) + 8 + len(b)
    out = struct.pack('<4sII', magic, version, total if length is None else length)
    out += struct.pack('<I4s', len(js), b'JSON') + js
    out += struct.pack('<I4s', len(b) if bin_chunk_len is None else bin_chunk_len, b'BIN\x00') + b
    return out


# --------------------------------------------------------------------------
# the corpus
# --------------------------------------------------------------------------

CASES = []


def case(name, defect, expect, khronos):
    def deco(fn):
        CASES.append((name, defect, expect, khronos, fn))
        return fn
    return deco


@case('index_out_of_range.gltf', 'index value 3 >= vertex count 3', 'index', ['ACCESSOR_INDEX_OOB'])
def _():
    d = base_doc(make_bin(indices=[0, 1, 3]))
    return gltf_text(d)


@case('accessor_past_bufferview.gltf',
      'POSITION accessor (3 x VEC3 float = 36 bytes) runs past its 24-byte bufferView',
      'bufferview', ['ACCESSOR_TOO_LONG'])
def _():
    d = base_doc()
    d['bufferViews'][0]['byteLength'] = 24
    return gltf_text(d)


@case('accessor_dangling_bufferview.gltf', 'accessor references bufferView 9 (only 4 exist)',
      'bufferview', ['UNRESOLVED_REFERENCE'])
def _():
    d = base_doc()
    d['accessors'][1]['bufferView'] = 9
    return gltf_text(d)


@case('misaligned_accessor_offset.gltf',
      'float POSITION accessor at byteOffset 2 (not a multiple of the 4-byte component size)',
      'align', ['ACCESSOR_OFFSET_ALIGNMENT', 'ACCESSOR_TOTAL_OFFSET_ALIGNMENT',
                'MESH_PRIMITIVE_ACCESSOR_UNALIGNED'])
def _():
    d = base_doc()
    d['bufferViews'][0]['byteLength'] = 40
    d['accessors'][0]['byteOffset'] = 2
    return gltf_text(d)


@case('bufferview_past_buffer.gltf', 'index bufferView (offset 96, length 64) runs past the 104-byte buffer',
      'buffer', ['BUFFER_VIEW_TOO_LONG'])
def _():
    d = base_doc()
    d['bufferViews'][3]['byteLength'] = 64
    return gltf_text(d)


@case('bufferview_offset_overflow.gltf',
      'bufferView byteOffset 4294967292 + byteLength 8 wraps a 32-bit sum (past the buffer)',
      'buffer', ['BUFFER_VIEW_TOO_LONG'])
def _():
    d = base_doc()
    d['bufferViews'][3]['byteOffset'] = 4294967292
    d['bufferViews'][3]['byteLength'] = 8
    return gltf_text(d)


@case('nonfinite_position.gltf', 'POSITION contains NaN (vertex 1 x) and +Inf (vertex 2 y)', 'finite',
      ['ACCESSOR_INVALID_FLOAT', 'ACCESSOR_MAX_MISMATCH', 'ACCESSOR_ELEMENT_OUT_OF_MAX_BOUND'])
def _():
    pos = list(POSITIONS)
    pos[3] = NAN
    pos[7] = INF
    d = base_doc(make_bin(positions=pos))
    # min/max of the finite values (JSON cannot express Inf, so the +Inf component
    # also makes the declared max mismatch in a strict validator)
    d['accessors'][0]['min'] = [0.0, 0.0, 0.0]
    d['accessors'][0]['max'] = [0.0, 0.0, 0.0]
    return gltf_text(d)


@case('nonfinite_node_matrix.gltf',
      'node matrix element [0] is 1e999 (+Inf as a double; nlohmann::json refuses it with '
      '"number overflow")', 'finite',
      ['VALUE_NOT_IN_RANGE'])
def _():
    d = base_doc()
    d['nodes'][0]['matrix'] = [1234567.5, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0,
                               0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0]
    txt = gltf_text(d).decode('utf-8')
    assert txt.count('1234567.5') == 1
    return txt.replace('1234567.5', '1e999').encode('utf-8')


@case('node_cycle.gltf', 'node 0 -> node 1 -> node 0 (a node is its own ancestor)', 'cycle',
      ['SCENE_NON_ROOT_NODE', 'NODE_LOOP'])
def _():
    d = base_doc()
    d['nodes'] = [{'name': 'a', 'mesh': 0, 'children': [1]}, {'name': 'b', 'children': [0]}]
    return gltf_text(d)


@case('node_self_child.gltf', 'node 0 lists itself as a child', 'cycle',
      ['SCENE_NON_ROOT_NODE', 'NODE_LOOP'])
def _():
    d = base_doc()
    d['nodes'] = [{'name': 'a', 'mesh': 0, 'children': [0]}]
    return gltf_text(d)


@case('node_two_parents.gltf', 'node 2 is a child of both node 0 and node 1', 'parent',
      ['NODE_PARENT_OVERRIDE'])
def _():
    d = base_doc()
    d['nodes'] = [{'name': 'p0', 'children': [2]}, {'name': 'p1', 'children': [2]},
                  {'name': 'shared', 'mesh': 0}]
    d['scenes'][0]['nodes'] = [0, 1]
    return gltf_text(d)


@case('dangling_mesh.gltf', 'node references mesh 5 (only 1 exists)', 'mesh', ['UNRESOLVED_REFERENCE'])
def _():
    d = base_doc()
    d['nodes'][0]['mesh'] = 5
    return gltf_text(d)


@case('negative_mesh_index.gltf', 'node references mesh -1', 'index', ['INVALID_INDEX'])
def _():
    d = base_doc()
    d['nodes'][0]['mesh'] = -1
    return gltf_text(d)


@case('dangling_material.gltf', 'primitive references material 3 (only 1 exists)', 'material',
      ['UNRESOLVED_REFERENCE'])
def _():
    d = base_doc()
    d['meshes'][0]['primitives'][0]['material'] = 3
    return gltf_text(d)


@case('dangling_texture.gltf', 'material baseColorTexture references texture 2 (no textures exist)',
      'texture', ['UNRESOLVED_REFERENCE'])
def _():
    d = base_doc()
    d['materials'][0]['pbrMetallicRoughness']['baseColorTexture'] = {'index': 2}
    return gltf_text(d)


@case('dangling_scene_node.gltf', 'scene lists node 7 (only 1 node exists)', 'node',
      ['UNRESOLVED_REFERENCE'])
def _():
    d = base_doc()
    d['scenes'][0]['nodes'] = [0, 7]
    return gltf_text(d)


@case('image_bufferview_out_of_range.glb', 'GLB image stored in bufferView 9 (only 4 exist)',
      'bufferview', ['UNRESOLVED_REFERENCE'])
def _():
    b = make_bin()
    d = base_doc(b, glb=True)
    d['images'] = [{'bufferView': 9, 'mimeType': 'image/png'}]
    d['textures'] = [{'source': 0}]
    d['materials'][0]['pbrMetallicRoughness']['baseColorTexture'] = {'index': 0}
    return glb_bytes(d, b)


@case('bad_data_uri_base64.gltf', 'buffer data URI payload is not valid base64', 'base64',
      ['INVALID_URI'])
def _():
    d = base_doc()
    d['buffers'][0]['uri'] = 'data:application/octet-stream;base64,AAAA*&^%$#@!notbase64=='
    return gltf_text(d)


@case('uri_parent_escape.gltf', "buffer URI '../../outside/triangle.bin' escapes the asset directory",
      'uri', ['IO_ERROR'])
def _():
    d = base_doc()
    d['buffers'][0]['uri'] = '../../outside/triangle.bin'
    return gltf_text(d)


@case('uri_absolute.gltf', "buffer URI is the absolute path '/etc/passwd'", 'uri', ['IO_ERROR'])
def _():
    d = base_doc()
    d['buffers'][0]['uri'] = '/etc/passwd'
    return gltf_text(d)


@case('uri_file_scheme.gltf', "buffer URI 'file:///etc/passwd' (absolute, with scheme)", 'uri',
      ['IO_ERROR'])
def _():
    d = base_doc()
    d['buffers'][0]['uri'] = 'file:///etc/passwd'
    return gltf_text(d)


@case('missing_bin.gltf', "buffer URI 'does_not_exist.bin' names a file that does not exist",
      'does_not_exist.bin', ['IO_ERROR'])
def _():
    d = base_doc()
    d['buffers'][0]['uri'] = 'does_not_exist.bin'
    return gltf_text(d)


@case('huge_index_accessor_count.gltf',
      'index accessor count 2^31 (u16: 2^32 bytes, wraps a 32-bit size to 0)', 'accessor',
      ['ACCESSOR_TOO_LONG'])
def _():
    d = base_doc()
    d['accessors'][3]['count'] = 2147483648
    return gltf_text(d)


@case('huge_position_accessor_count.gltf',
      'POSITION accessor count 357913942 (x 12 bytes wraps a 32-bit size to 8)', 'accessor',
      ['ACCESSOR_TOO_LONG'])
def _():
    d = base_doc()
    for a in d['accessors'][:3]:
        a['count'] = 357913942
    return gltf_text(d)


@case('truncated.glb', 'GLB header declares the full length but the file is cut inside the BIN chunk',
      'truncated', ['GLB_UNEXPECTED_END_OF_CHUNK_DATA'])
def _():
    b = make_bin()
    full = glb_bytes(base_doc(b, glb=True), b)
    return full[:len(full) - 60]


@case('truncated_header.glb', 'GLB file only 8 bytes long (header cut)', 'header',
      ['GLB_UNEXPECTED_END_OF_HEADER'])
def _():
    b = make_bin()
    return glb_bytes(base_doc(b, glb=True), b)[:8]


@case('bad_magic.glb', "GLB magic is 'glTX' instead of 'glTF'", 'magic', ['GLB_INVALID_MAGIC'])
def _():
    b = make_bin()
    return glb_bytes(base_doc(b, glb=True), b, magic=b'glTX')


@case('bad_version.glb', 'GLB container version 1 (must be 2)', 'version', ['GLB_INVALID_VERSION'])
def _():
    b = make_bin()
    return glb_bytes(base_doc(b, glb=True), b, version=1)


@case('chunk_past_end.glb', 'GLB BIN chunk length field claims 1000 bytes more than the file holds',
      'chunk', ['GLB_CHUNK_TOO_BIG', 'GLB_UNEXPECTED_END_OF_CHUNK_DATA'])
def _():
    b = make_bin()
    return glb_bytes(base_doc(b, glb=True), b, bin_chunk_len=len(b) + 1000)


@case('empty.gltf', 'empty file (0 bytes), .gltf extension', 'empty', ['FORMAT'])
def _():
    return b''


@case('empty.glb', 'empty file (0 bytes), .glb extension', 'empty', ['FORMAT'])
def _():
    return b''


@case('json_syntax_error.gltf', 'JSON syntax error (a comma is missing between two members)', 'json',
      ['INVALID_JSON'])
def _():
    txt = gltf_text(base_doc()).decode('utf-8')
    needle = '"scene": 0,'
    assert txt.count(needle) == 1
    return txt.replace(needle, '"scene": 0').encode('utf-8')


@case('json_truncated.gltf', 'JSON text cut off in the middle of the document', 'json',
      ['INVALID_JSON'])
def _():
    txt = gltf_text(base_doc())
    return txt[:len(txt) // 2]


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(here), 'tests', 'data')
    bad = os.path.join(out, 'bad_gltf')
    os.makedirs(bad, exist_ok=True)

    def write(path, data):
        assert len(data) < 20 * 1024, path
        with open(path, 'wb') as f:
            f.write(data)
        print('wrote %-50s %6d bytes' % (os.path.relpath(path, out), len(data)))

    b = make_bin()
    write(os.path.join(out, 'good_triangle.gltf'), gltf_text(base_doc(b)))
    write(os.path.join(out, 'good_triangle.glb'), glb_bytes(base_doc(b, glb=True), b))
    manifest = []
    names = set()
    for name, defect, expect, khronos, fn in CASES:
        assert name not in names, name
        names.add(name)
        assert expect == expect.lower()
        write(os.path.join(bad, name), fn())
        manifest.append({'file': name, 'defect': defect, 'expect': expect,
                         'format': 'glb' if name.endswith('.glb') else 'gltf', 'khronos': khronos})
    with open(os.path.join(bad, 'manifest.json'), 'w') as f:
        f.write(json.dumps(manifest, indent=2) + '\n')
    print('%d malformed files + manifest.json in %s' % (len(manifest), os.path.relpath(bad, out)))


if __name__ == '__main__':
    main()
