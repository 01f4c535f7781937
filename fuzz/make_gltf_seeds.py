#!/usr/bin/env python3
"""Writes the glTF fuzzer's seeds: a 3-node, 2-joint skin animated by LINEAR and STEP samplers,
as corpus-gltf/arm.gltf.seed (embedded base64 buffer) and corpus-gltf/arm.glb.seed (extensions that no data filter mistakes for mocap). Run from fuzz/."""
import base64
import json
import os
import struct


def floats(values):
    return struct.pack("<%df" % len(values), *values)


def main():
    parts = [floats([0.0, 1 / 60, 2 / 60]),                                          # key times
             floats([0, 0, 0, 1, 0, 0, 0.3826834, 0.9238795, 0, 0, 0.7071068, 0.7071068]),  # rotations
             floats([0, 0, 0, 0, 0, 0.1, 0, 0, 0.2])]                               # translations
    views, offset = [], 0
    for p in parts:
        views.append({"buffer": 0, "byteOffset": offset, "byteLength": len(p)})
        offset += len(p)
    blob = b"".join(parts)
    doc = {
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"name": "Armature", "translation": [1, 0, 0], "children": [1]},
                  {"name": "root", "children": [2]}, {"name": "tip", "translation": [0, 1, 0]}],
        "skins": [{"joints": [1, 2]}],
        "animations": [{"channels": [{"sampler": 0, "target": {"node": 1, "path": "rotation"}},
                                     {"sampler": 1, "target": {"node": 1, "path": "translation"}}],
                        "samplers": [{"input": 0, "output": 1, "interpolation": "LINEAR"},
                                     {"input": 0, "output": 2, "interpolation": "STEP"}]}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "SCALAR"},
                      {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC4"},
                      {"bufferView": 2, "componentType": 5126, "count": 3, "type": "VEC3"}],
        "bufferViews": views,
        "buffers": [{"byteLength": len(blob),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(blob).decode()}],
    }
    os.makedirs("corpus-gltf", exist_ok=True)
    with open("corpus-gltf/arm.gltf.seed", "w") as f:
        f.write(json.dumps(doc, indent=1) + "\n")
    doc["buffers"] = [{"byteLength": len(blob)}]
    text = json.dumps(doc).encode()
    text += b" " * (-len(text) % 4)
    glb = (b"glTF" + struct.pack("<II", 2, 12 + 8 + len(text) + 8 + len(blob)) +
           struct.pack("<I", len(text)) + b"JSON" + text + struct.pack("<I", len(blob)) + b"BIN\0" + blob)
    with open("corpus-gltf/arm.glb.seed", "wb") as f:
        f.write(glb)


if __name__ == "__main__":
    main()
