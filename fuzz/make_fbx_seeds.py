#!/usr/bin/env python3
"""Writes the FBX fuzzer's binary seeds, corpus-fbx/walk_binary.fbx.seed and walk_binary_zlib.fbx.seed: the
two-joint walk of tests/support/ascii_fbx.h (hips with a keyed X translation, a hand 0.5 along X, 30 fps,
metres) as a binary FBX 7400, its key arrays stored plain and zlib-compressed, so the fuzzer starts inside
the binary tokenizer, the connection scan and the compressed arrays. (corpus-fbx/walk.fbx.seed is the
ASCII file that header writes.) Run from fuzz/."""
import os
import struct
import zlib

TICKS = 46186158000  # FBX time units per second


def prop(value):
    kind, v = value
    if kind == "S":
        return b"S" + struct.pack("<I", len(v)) + v
    if kind in "ILD":
        return kind.encode() + struct.pack({"I": "<i", "L": "<q", "D": "<d"}[kind], v)
    deflate = kind.endswith("z")  # "lz", "fz": the array zlib-compressed
    kind = kind[0]
    data = struct.pack("<%d%s" % (len(v), {"l": "q", "f": "f"}[kind]), *v)
    stored = zlib.compress(data) if deflate else data
    return kind.encode() + struct.pack("<III", len(v), int(deflate), len(stored)) + stored


def node(name, props=(), children=None, offset=0):
    """Record at file offset `offset`: end offset, property count and bytes, name, properties, children
    (a list, possibly empty, makes a scope: closed by a null record)."""
    body = b"".join(prop(p) for p in props)
    head = 13 + len(name)
    out_children = b""
    for child in children or []:
        out_children += child(offset + head + len(body) + len(out_children))
    if children is not None:
        out_children += b"\0" * 13
    end = offset + head + len(body) + len(out_children)
    return struct.pack("<IIIB", end, len(props), len(body), len(name)) + name + body + out_children


def n(name, props=(), children=None):
    return lambda offset: node(name, props, children, offset)


def s(text):
    return ("S", text.encode() if isinstance(text, str) else text)


def p70(*entries):
    return n(b"Properties70", children=[n(b"P", e) for e in entries])


def walk(deflate):
    """The file's bytes, its key arrays zlib-compressed when `deflate`."""
    z = "z" if deflate else ""
    times = [0, TICKS // 20, TICKS // 10]
    top = [
        n(b"FBXHeaderExtension", children=[n(b"FBXHeaderVersion", [("I", 1003)]), n(b"FBXVersion", [("I", 7400)])]),
        n(b"GlobalSettings", children=[n(b"Version", [("I", 1000)]), p70(
            [s("UpAxis"), s("int"), s("Integer"), s(""), ("I", 1)],
            [s("UpAxisSign"), s("int"), s("Integer"), s(""), ("I", 1)],
            [s("UnitScaleFactor"), s("double"), s("Number"), s(""), ("D", 100.0)],
            [s("TimeMode"), s("enum"), s(""), s(""), ("I", 6)])]),
        n(b"Objects", children=[
            n(b"NodeAttribute", [("L", 2001), s(b"\0\x01NodeAttribute"), s("LimbNode")],
              [n(b"TypeFlags", [s("Skeleton")])]),
            n(b"Model", [("L", 1001), s(b"hips\0\x01Model"), s("LimbNode")], [n(b"Version", [("I", 232)]), p70(
                [s("Lcl Translation"), s("Lcl Translation"), s(""), s("A"), ("D", 0.0), ("D", 1.0), ("D", 0.0)])]),
            n(b"NodeAttribute", [("L", 2002), s(b"\0\x01NodeAttribute"), s("LimbNode")],
              [n(b"TypeFlags", [s("Skeleton")])]),
            n(b"Model", [("L", 1002), s(b"hand\0\x01Model"), s("LimbNode")], [n(b"Version", [("I", 232)]), p70(
                [s("Lcl Translation"), s("Lcl Translation"), s(""), s("A"), ("D", 0.5), ("D", 0.0), ("D", 0.0)])]),
            n(b"AnimationStack", [("L", 3001), s(b"walk\0\x01AnimStack"), s("")], []),
            n(b"AnimationLayer", [("L", 3002), s(b"Base\0\x01AnimLayer"), s("")], []),
            n(b"AnimationCurveNode", [("L", 3003), s(b"T\0\x01AnimCurveNode"), s("")], [p70(
                [s("d|X"), s("Number"), s(""), s("A"), ("D", 0.0)],
                [s("d|Y"), s("Number"), s(""), s("A"), ("D", 1.0)],
                [s("d|Z"), s("Number"), s(""), s("A"), ("D", 0.0)])]),
            n(b"AnimationCurve", [("L", 3004), s(b"\0\x01AnimCurve"), s("")], [
                n(b"Default", [("D", 0.0)]), n(b"KeyVer", [("I", 4009)]),
                n(b"KeyTime", [("l" + z, times)]), n(b"KeyValueFloat", [("f" + z, [0.0, 0.1, 0.3])])]),
        ]),
        n(b"Connections", children=[n(b"C", [s("OP" if p else "OO"), ("L", a), ("L", b)] + ([s(p)] if p else []))
                                    for a, b, p in [(1001, 0, None), (2001, 1001, None), (1002, 1001, None),
                                                    (2002, 1002, None), (3002, 3001, None), (3003, 3002, None),
                                                    (3003, 1001, "Lcl Translation"), (3004, 3003, "d|X")]]),
    ]
    out = b"Kaydara FBX Binary  \0\x1a\0" + struct.pack("<I", 7400)
    for record in top:
        out += record(len(out))
    return out + b"\0" * 13


def main():
    os.makedirs("corpus-fbx", exist_ok=True)
    for name, deflate in (("walk_binary", False), ("walk_binary_zlib", True)):
        with open("corpus-fbx/%s.fbx.seed" % name, "wb") as f:
            f.write(walk(deflate))


if __name__ == "__main__":
    main()
