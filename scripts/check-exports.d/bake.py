"""Reads a Systole bake (docs/bake-format.md): the simulated render-mesh positions, float64."""
import struct


def read_bake(path):
    """Returns (fps, {organ name: [frame][vertex] -> (x, y, z)} as lists of flat float lists)."""
    with open(path, 'rb') as f:
        data = f.read()
    assert data[:8] == b'SYSBAKE\n', path
    version, organs, frames, _flags = struct.unpack_from('<4I', data, 8)
    fps, = struct.unpack_from('<d', data, 24)
    at = 40
    layout = []
    for _ in range(organs):
        n, name_bytes = struct.unpack_from('<2I', data, at)
        at += 8
        layout.append((data[at:at + name_bytes].decode(), n))
        at += name_bytes
    out = {name: [] for name, _ in layout}
    for _ in range(frames):
        for name, n in layout:
            out[name].append(struct.unpack_from('<%dd' % (3 * n), data, at))
            at += 24 * n
    return fps, out
