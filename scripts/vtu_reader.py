"""The DataArrays of the VTU files glissade writes (deal.II's DataOut):
ASCII, raw base64 or zlib-compressed base64. Used by plot_scene.py and the
peers' comparisons (benchmarks/peers/multi_body_race.py)."""
import base64
import math
import re
import struct
import zlib

VTK_TYPES = {"Float32": "f", "Float64": "d", "Int32": "i", "Int64": "q",
             "UInt8": "B", "UInt32": "I", "UInt64": "Q"}


def vtu_arrays(path):
    """The DataArrays of a VTU file by name ("Points" for the points), as
    flat lists: ASCII, or deal.II's binary (base64 of a header of UInt32
    block sizes, then of the zlib-compressed blocks)."""
    with open(path) as f:
        text = f.read()
    compressed = "vtkZLibDataCompressor" in text[:1000]
    arrays = {}
    for match in re.finditer(r"<DataArray([^>]*)>(.*?)</DataArray>", text, re.S):
        attributes, body = match.group(1), match.group(2).strip()
        kind = re.search(r'type="(\w+)"', attributes).group(1)
        name = re.search(r'Name="([^"]*)"', attributes)
        name = name.group(1) if name else "Points"
        if 'format="ascii"' in attributes:
            values = [float(v) for v in body.split()]
        else:
            code = VTK_TYPES[kind]
            if compressed:
                n_blocks = struct.unpack("<I", base64.b64decode(body[:8])[:4])[0]
                header_chars = 4 * math.ceil(4 * (3 + n_blocks) / 3)
                header = struct.unpack(f"<{3 + n_blocks}I",
                                       base64.b64decode(body[:header_chars]))
                data = base64.b64decode(body[header_chars:])
                raw, start = b"", 0
                for size in header[3:]:
                    raw += zlib.decompress(data[start:start + size])
                    start += size
            else:
                raw = base64.b64decode(body)[4:]
            values = list(struct.unpack(f"<{len(raw) // struct.calcsize(code)}{code}", raw))
        arrays[name] = values
    return arrays
