import base64, math, struct, zlib, sys, glob, os

def decode(b64, typ):
    nb = struct.unpack("<Q", base64.b64decode(b64[:12])[:8])[0]
    hlen = 8 * (3 + nb)
    hchars = 4 * math.ceil(hlen / 3)
    sizes = struct.unpack(f"<{3 + nb}Q", base64.b64decode(b64[:hchars])[:hlen])[3:]
    data = base64.b64decode(b64[hchars:])
    out, off = b"", 0
    for s in sizes:
        out += zlib.decompress(data[off:off + s]); off += s
    fmt = {"Float64": "d", "Int64": "q", "Int32": "i", "UInt8": "B", "Float32": "f"}[typ]
    n = len(out) // struct.calcsize(fmt)
    return struct.unpack(f"<{n}{fmt}", out)

def read_vtu(path):
    text = open(path, encoding="utf-8").read()
    arrays = {}; pos = 0
    while True:
        i = text.find("<DataArray", pos)
        if i < 0: break
        j = text.find(">", i); head = text[i:j]
        k = text.find("</DataArray>", j); body = text[j + 1:k].strip(); pos = k
        name = head.split('Name="')[1].split('"')[0] if 'Name="' in head else "Points"
        typ = head.split('type="')[1].split('"')[0]
        nc = int(head.split('NumberOfComponents="')[1].split('"')[0]) if 'NumberOfComponents="' in head else 1
        if name in ("connectivity", "offsets", "types"): continue
        d = decode(body, typ)
        arrays[name] = [d[i*nc:(i+1)*nc] for i in range(len(d)//nc)] if nc > 1 else list(d)
    return arrays
