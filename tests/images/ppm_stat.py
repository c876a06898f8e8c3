#!/usr/bin/env python3
"""tests/images/ppm_stat.py IMAGE.ppm covered|mean: one number about a binary
PPM (P6, 8 bits) for the image tests.
  covered  how many pixels differ from the top-left one (the background)
  mean     the mean of all its bytes, rounded down"""
import sys


def pixels(path):
    data = open(path, "rb").read()
    parts = data.split(maxsplit=4)
    w, h = int(parts[1]), int(parts[2])
    return parts[4][-w * h * 3:]


def main():
    if len(sys.argv) != 3 or sys.argv[2] not in ("covered", "mean"):
        sys.exit("usage: ppm_stat.py IMAGE.ppm covered|mean")
    px = pixels(sys.argv[1])
    if sys.argv[2] == "covered":
        bg = px[:3]
        print(sum(1 for i in range(0, len(px), 3) if px[i:i + 3] != bg))
    else:
        print(sum(px) // len(px))


main()
