"""Readers of OpenFOAM ASCII files for the tutorials' and tests' Python
scripts: lagrangian IOField lists, the Cartesian 'positions' file, and the
internal field of volume fields; write_field replaces the values of a
lagrangian scalar IOField. etc/bashrc puts this folder on PYTHONPATH."""
import re

import numpy as np


def _list_values(body, path):
    """The first list of body ('N(...)', 'N{v}' or 'N\\n(\\n...\\n)'), scalar
    or vector, as an (N,) or (N,3) array."""
    m = re.search(r"(\d+)\s*([({])", body)
    if not m:
        raise ValueError(f"{path}: no list found")
    n, opener = int(m.group(1)), m.group(2)
    rest = body[m.end():]
    if opener == "{":                       # uniform list N{value}
        inner = rest[:rest.index("}")]
        v = np.array(inner.replace("(", " ").replace(")", " ").split(), dtype=float)
        return np.tile(v, (n, 1)) if v.size > 1 else np.full(n, v[0])
    depth, end = 1, 0
    for i, c in enumerate(rest):
        depth += (c == "(") - (c == ")")
        if depth == 0:
            end = i
            break
    inner = rest[:end]
    if "(" in inner:                        # vectors
        rows = re.findall(r"\(([^()]*)\)", inner)
        arr = np.array([r.split() for r in rows], dtype=float).reshape(-1, 3)
    else:
        arr = np.array(inner.split(), dtype=float)
    if len(arr) != n:
        raise ValueError(f"{path}: {len(arr)} values, header says {n}")
    return arr


def read_field(path):
    """Values of an ASCII IOField (scalar or vector) as an (N,) or (N,3) array;
    handles the list forms 'N(...)', 'N{v}' and 'N\\n(\\n...\\n)'."""
    body = open(path).read().split("// * * *", 1)[-1]
    return _list_values(re.sub(r"//.*", "", body), path)


def write_field(path, values):
    """Replace the list of an ASCII scalar IOField by values (same header)."""
    text = open(path).read()
    head, body = text.split("// * * *", 1)
    star, rest = body.split("\n", 1)
    listed = "%d\n(\n%s\n)\n" % (len(values),
                                    "\n".join("%.17g" % v for v in values))
    open(path, "w").write(head + "// * * *" + star + "\n\n" + listed)


def read_internal_field(path, n=None):
    """internalField of an ASCII volume field (scalar or vector): the array
    of a nonuniform field; a uniform one as its value, or repeated n times
    when n is given."""
    text = open(path).read()
    m = re.search(r"internalField\s+uniform\s+(\([^)]*\)|[-+0-9.eE]+)", text)
    if m:
        v = np.array(m.group(1).strip("()").split(), dtype=float)
        if n is not None:
            return np.tile(v, (n, 1)) if v.size > 1 else np.full(n, v[0])
        return v if v.size > 1 else float(v[0])
    m = re.search(r"internalField\s+nonuniform\s+List<\w+>", text)
    if not m:
        raise ValueError(f"{path}: no internalField")
    return _list_values(text[m.end():], path)


def read_positions(path):
    """Cartesian positions of a 'positions' file: lines '(x y z) celli'."""
    text = open(path).read().split("// * * *", 1)[-1]
    rows = re.findall(r"\(\s*([-+0-9.eE]+)\s+([-+0-9.eE]+)\s+([-+0-9.eE]+)\s*\)\s+-?\d+", text)
    return np.array(rows, dtype=float).reshape(-1, 3)


def read_particle_history(case, cloud="cloud"):
    """The particleHistory function object's samples of a case (all its
    start-time folders, in order): the data as an (N, columns) array and
    the column index of each header name."""
    import glob
    import os
    files = sorted(glob.glob(os.path.join(
        case, "postProcessing", "lagrangian", cloud, "particleHistory", "*",
        "particleHistory.dat")))
    if not files:
        raise FileNotFoundError(f"{case}: no particleHistory.dat")
    header = open(files[0]).readlines()[1].lstrip("# ").split()
    data = np.vstack([np.loadtxt(f, ndmin=2) for f in files])
    return data, {h: i for i, h in enumerate(header)}
