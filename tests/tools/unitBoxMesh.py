#!/usr/bin/env python3
"""Rewrite system/blockMeshDict of a case copied from a tutorial into a 1 m
unit cube of 4 x 4 x 4 cells, its faces walls or cyclic pairs (x0/x1,
y0/y1, z0/z1), or a duct cyclic in x with walls (xCyclic): the box of
several case tests.

    unitBoxMesh.py wall|cyclic|xCyclic [caseDir]
"""
import os
import re
import sys

PATCHES = {
    "wall": """    walls { type wall; faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2) (0 3 2 1) (4 5 6 7)); }""",
    "cyclic": """    x0 { type cyclic; neighbourPatch x1; faces ((0 4 7 3)); }
    x1 { type cyclic; neighbourPatch x0; faces ((1 2 6 5)); }
    y0 { type cyclic; neighbourPatch y1; faces ((0 1 5 4)); }
    y1 { type cyclic; neighbourPatch y0; faces ((3 7 6 2)); }
    z0 { type cyclic; neighbourPatch z1; faces ((0 3 2 1)); }
    z1 { type cyclic; neighbourPatch z0; faces ((4 5 6 7)); }""",
    "xCyclic": """    x0 { type cyclic; neighbourPatch x1; faces ((0 4 7 3)); }
    x1 { type cyclic; neighbourPatch x0; faces ((1 2 6 5)); }
    walls { type wall; faces ((0 1 5 4) (3 7 6 2) (0 3 2 1) (4 5 6 7)); }""",
}


def main():
    kind = sys.argv[1]
    p = os.path.join(sys.argv[2] if len(sys.argv) > 2 else ".", "system", "blockMeshDict")
    s = open(p).read()
    s = re.sub(r"^scale .*?;", "scale 1;", s, flags=re.M)
    s = re.sub(r"vertices\s*\(.*?\);", """vertices
(
    (0 0 0) (1 0 0) (1 1 0) (0 1 0) (0 0 1) (1 0 1) (1 1 1) (0 1 1)
);""", s, flags=re.S)
    s = re.sub(r"blocks\s*\(.*?\);", "blocks\n(\n    hex (0 1 2 3 4 5 6 7) (4 4 4) simpleGrading (1 1 1)\n);",
               s, flags=re.S)
    s = re.sub(r"boundary\s*\(.*\);", "boundary\n(\n" + PATCHES[kind] + "\n);", s, flags=re.S)
    open(p, "w").write(s)


if __name__ == "__main__":
    main()
