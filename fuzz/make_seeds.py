# Writes the binary seeds of fuzz_geometry, fuzz_mesh and fuzz_output (decoded by fuzz/harness.hpp's ByteReader).
import os, struct, sys
root = sys.argv[1]
def num(v):
    # ByteReader::number: kind 5 -> 0, 6 -> 1, 1 -> int8, 0 -> raw double
    if v == 0: return b'\x05'
    if v == 1: return b'\x06'
    if float(v).is_integer() and -128 <= v <= 127: return b'\x01' + struct.pack('b', int(v))
    return b'\x00' + struct.pack('<d', v)
def pt(x, y, z): return num(x) + num(y) + num(z)
def weight(w):  # 0.25 + (k % 16) / 4
    return bytes([int(round((w - 0.25) * 4)) % 16 + 16])
def write(target, name, data):
    d = os.path.join(root, target); os.makedirs(d, exist_ok=True)
    open(os.path.join(d, name), 'wb').write(data)

# op 0: Bezier curve, 3 points, rational, weights count = count; 2 queries
write('fuzz_geometry', 'bezier_curve_rational', b'\x00' + b'\x02' + pt(0,0,0) + pt(1,2,0) + pt(3,0,1)
      + b'\x01' + b'\x01' + weight(1) + weight(0.5) + weight(1) + b'\x01' + b'\x01\x80' + b'\x02' + b'\x00' + num(0.5) + b'\x03')
# op 1: Bezier surface 2x3 polynomial
net = b''.join(pt(i, j, (i * j) % 3) for i in range(2) for j in range(3))
write('fuzz_geometry', 'bezier_surface', b'\x01' + b'\x01' + b'\x02' + net + b'\x00' + b'\x00' + b'\x01\x40\x01\xc0\x02\x01\x01')
# op 2: NURBS curve degree 2, 4 points, knots clamped uniform steps of 1
knots = b'\x01' + bytes([1]) * 8
write('fuzz_geometry', 'nurbs_curve', b'\x02' + b'\x02' + b'\x03' + b'\x01' + knots + pt(0,0,0) + pt(1,1,0) + pt(2,-1,0) + pt(3,0,0)
      + b'\x01' + weight(1) + weight(2) + weight(0.5) + weight(1) + b'\x02' + b'\x01\x40\x03\x02\x01\x90\x01')
# op 3: NURBS surface degree (2,1), 3x2 points
write('fuzz_geometry', 'nurbs_surface', b'\x03' + b'\x02' + b'\x01' + b'\x02' + b'\x01' + b'\x01' + bytes([1]) * 8 + b'\x01' + bytes([1]) * 8
      + b''.join(pt(i, j, i * j) for i in range(3) for j in range(2)) + b'\x00' + b'\x01\x01\x40\x01\x40\x02\x02\x01')
# Profiles for ops 4 and 5 (fuzz_geometry.cpp's decode_profile): a count byte (1 + b % 4 pieces), the
# pieces, then a flag that would close the profile with one more line (0 here: they close already).
def line(a, b):  # flag 0 = NURBS piece; degree 1; 1 + 1 = 2 points; knot count as usual; knots clamped
    # (mode 1) with one step of 1: {0, 0, 1, 1}; the points; weights flag 0 (polynomial)
    return b'\x00' + b'\x01' + b'\x01' + b'\x01' + b'\x01' + b'\x01' + a + b + b'\x00'
def bezier_piece(points, weights, first):  # flag 1 = Bezier piece; 2 + (n - 2) points; joined flag after
    # the first piece (0: the points already join); per weight a flag 0 then the weight byte
    return (b'\x01' + bytes([len(points) - 2]) + b''.join(points) + (b'' if first else b'\x00')
            + b''.join(b'\x00' + weight(w) for w in weights))
def profile(pieces): return bytes([len(pieces) - 1]) + b''.join(pieces) + b'\x00'
# op 4: revolve a closed profile about the z axis (axis flags 0, 0): a rational quadratic and three lines,
# in full (angle flag 1) and by 270 degrees; the last byte sets the tessellation tolerance
ring = profile([bezier_piece([pt(2,0,0), pt(4,0,1), pt(2,0,2)], [1, 2, 1], True),
                line(pt(2,0,2), pt(2,0,1)), line(pt(2,0,1), pt(3,0,1)), line(pt(3,0,1), pt(2,0,0))])
write('fuzz_geometry', 'revolve_full', b'\x04' + ring + b'\x00' + b'\x00' + b'\x01' + b'\x10')
write('fuzz_geometry', 'revolve_partial', b'\x04' + ring + b'\x00' + b'\x00' + b'\x00' + num(270) + b'\x10')
# op 4 again: a bow tie in the xz plane, whose sides cross at (1.5, 0, 0.5): revolve refuses it
bow_tie = profile([line(pt(1,0,0), pt(2,0,1)), line(pt(2,0,1), pt(2,0,0)), line(pt(2,0,0), pt(1,0,1)),
                   line(pt(1,0,1), pt(1,0,0))])
write('fuzz_geometry', 'revolve_bow_tie', b'\x04' + bow_tie + b'\x00' + b'\x00' + b'\x01' + b'\x10')
# op 5: extrude a closed planar profile along z (direction flag 1, then the point) by 2
triangle = profile([line(pt(0,0,0), pt(2,0,0)), line(pt(2,0,0), pt(1,2,0)),
                    bezier_piece([pt(1,2,0), pt(0,1,0), pt(0,0,0)], [1, 3, 1], False)])
write('fuzz_geometry', 'extrude', b'\x05' + triangle + b'\x01' + pt(0,0,1) + num(2) + b'\x08')

# fuzz_mesh: a tetrahedron on the integer grid (grid flag), outward triangles, self-intersection check on
def mesh_seed(verts, tris, grid=True, si=True):
    data = bytes([len(verts), len(tris), 1 if grid else 0])
    for v in verts:
        data += bytes((c + 2) for c in v) if grid else pt(*v)
    for t in tris:
        data += bytes(t)
    return data + bytes([1 if si else 0])
tet_v = [(0,0,0),(1,0,0),(0,1,0),(0,0,1)]
tet_t = [(0,2,1),(0,1,3),(0,3,2),(1,2,3)]
write('fuzz_mesh', 'tetrahedron', mesh_seed(tet_v, tet_t))
write('fuzz_mesh', 'tetrahedron_inward', mesh_seed(tet_v, [(a, c, b) for a, b, c in tet_t]))
write('fuzz_mesh', 'tetrahedron_open', mesh_seed(tet_v, tet_t[:3]))
write('fuzz_mesh', 'tetrahedron_float', mesh_seed([(0.5,0,0),(1e10,0,0),(0,-0.0,1e-300),(0,0,1)], tet_t, grid=False))
cube_v = [(x, y, z) for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)]
cube_t = [(0,1,3),(0,3,2),(4,6,7),(4,7,5),(0,4,5),(0,5,1),(2,3,7),(2,7,6),(0,2,6),(0,6,4),(1,5,7),(1,7,3)]
write('fuzz_mesh', 'cube', mesh_seed(cube_v, cube_t))
write('fuzz_mesh', 'index_out_of_range', mesh_seed(tet_v, tet_t[:3] + [(1, 2, 5)]))

# fuzz_output (fuzz_output.cpp's write_once): writes count (1 + b % 3), then per write: name kind (b % 8; 0 is
# "out<k>.scad" with k = b % 3), what is planted (b % 6: nothing, file, read-only file, link to a file outside,
# dangling link, folder), the byte count (b % 65) and bytes, the failure (b % 4: 0 none, 2 Error, 3 another
# exception), where it fails (b % 65, modulo the size), and the entry point (b & 1: write_file_by_name).
def output_write(name, plant, data, failure=0, fail_after=0, by_name=0):
    return name + bytes([plant, len(data)]) + data + bytes([failure, fail_after, by_name])
plain = lambda k: bytes([0, k])
for plant, what in enumerate(['new', 'over_file', 'over_read_only', 'over_link', 'over_dangling_link', 'over_folder']):
    write('fuzz_output', what, b'\x00' + output_write(plain(0), plant, b'solid'))
    write('fuzz_output', what + '_by_name', b'\x00' + output_write(plain(0), plant, b'ISO-10303-21;', by_name=1))
write('fuzz_output', 'writer_error_part_way', b'\x00' + output_write(plain(1), 1, b'0123456789', failure=2, fail_after=4))
write('fuzz_output', 'writer_exception_by_name', b'\x00' + output_write(plain(1), 1, b'0123456789', failure=3, fail_after=7, by_name=1))
write('fuzz_output', 'name_too_long', b'\x00' + output_write(bytes([2, 16]), 0, b'x'))
write('fuzz_output', 'name_with_nul', b'\x00' + output_write(bytes([3]), 0, b'x'))
write('fuzz_output', 'missing_folder', b'\x00' + output_write(bytes([4]), 0, b'x'))
write('fuzz_output', 'under_a_file', b'\x00' + output_write(bytes([5]), 0, b'x'))
write('fuzz_output', 'dot_names', b'\x01' + output_write(bytes([6, 0]), 0, b'x') + output_write(bytes([6, 1]), 0, b'x'))
write('fuzz_output', 'odd_bytes', b'\x00' + output_write(bytes([1, 5]) + b"\x1b[2J\n!", 0, b'x'))
write('fuzz_output', 'three_writes_one_name', b'\x02' + output_write(plain(2), 0, b'first') + output_write(plain(2), 0, b'second', 2, 3)
      + output_write(plain(2), 0, b'third', 0, 0, 1))
