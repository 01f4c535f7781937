#!/usr/bin/env python3
"""Prints the colour-map tables of src/render/colour_map.cpp: 33 evenly spaced entries of matplotlib's
viridis (van der Walt and Smith, CC0) and coolwarm (Moreland's diverging map), linearly interpolated
by colour_at(). Needs Debian's python3-matplotlib: /usr/bin/python3 scripts/colour_tables.py"""
from matplotlib import colormaps

ENTRIES = 33

for name in ("viridis", "coolwarm"):
    cmap = colormaps[name]
    print(f"// {name}")
    for i in range(ENTRIES):
        r, g, b, _ = cmap(i / (ENTRIES - 1))
        print(f"    {{{r:.4f}f, {g:.4f}f, {b:.4f}f}},")
