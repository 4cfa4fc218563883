#!/usr/bin/env python3
"""Writes a cpfg colour map (.map: 256 colours of three sRGB bytes, indexed by the turtle's `;`).

Usage: tools/colormap.py OUT.map ENTRY...
  ENTRY is INDEX:#rrggbb, or FIRST-LAST:#rrggbb for a range of one colour, or FIRST-LAST:#rrggbb..#rrggbb for a
  range shaded from one colour to the other. Entries not given take entry 1's colour (the turtle's first).
Example: tools/colormap.py gold-on-red.map 0:#9b1b1e 1:#e8b64c 2-3:#f3d68a..#c98f2e
"""
import sys


def rgb(text):
    if len(text) != 7 or text[0] != '#':
        raise ValueError(f"expected #rrggbb, not {text!r}")
    return tuple(int(text[i:i + 2], 16) for i in (1, 3, 5))


def main(argv):
    if len(argv) < 3:
        sys.exit(__doc__)
    colours = {}
    for entry in argv[2:]:
        where, _, what = entry.partition(':')
        first, _, last = where.partition('-')
        first, last = int(first), int(last or first)
        if not 0 <= first <= last <= 255:
            sys.exit(f"{entry}: indices run from 0 to 255")
        start, _, end = what.partition('..')
        a, b = rgb(start), rgb(end or start)
        for i in range(first, last + 1):
            t = 0 if last == first else (i - first) / (last - first)
            colours[i] = tuple(round(a[c] + t * (b[c] - a[c])) for c in range(3))
    fill = colours.get(1, (255, 255, 255))
    data = bytes(v for i in range(256) for v in colours.get(i, fill))
    with open(argv[1], 'wb') as out:
        out.write(data)


if __name__ == '__main__':
    main(sys.argv)
