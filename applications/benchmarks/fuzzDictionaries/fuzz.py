#!/usr/bin/python3
"""Fuzz the dictionaries of chargedFoam's tutorials.

Copies a few small, fast tutorials, prepares each once (mesh, parcels, a run
of a few time steps, contact within those steps), then applies N seeded
mutations, one per run, to an entry of constant/cloudProperties, of the
parcels (in cloudProperties or constant/parcels), of system/fvSolution or of
constant/carrierProperties: delete it, give it a wrong type, make it
negative, zero, huge (1e300), tiny (1e-200: the reader reads values below
1e-300 as 0), nan or inf (as typed, which the reader refuses, or as #eval{}
expressions with FOAM_SIGFPE=false, which reach the code), misspell its
name, add a misspelt copy next to it, or misspell a word value. Each
mutated case runs its solver for the few steps and is classified:

  ok        ran, nothing non-finite written, the change plausibly harmless
  accepted  ran, nothing non-finite written, although the value is invalid
            on its face (negative, non-finite, huge, wrong type) -- often an
            entry the case does not read
  error     exit != 0 with a FOAM FATAL (IO) ERROR; 'named' when the message
            names the mutated entry, 'file' when only its dictionary
  crash     a signal (exit >= 128, segmentation fault, floating point
            exception, terminate called, abort) or a failure without a FOAM
            error message
  hang      still running after --timeout seconds
  nan       ran, but nan or inf in a written field or lagrangian file

Escapes (crash, hang, nan, errors naming neither the entry nor its file) are
listed with the mutation that reproduces them (--only ID reruns one and keeps
its case) in <work>/fuzz.md (every run in <work>/results.json); the last
line printed is the summary.

    fuzz.py [--n 1000] [--seed 1] [--work /tmp/fuzz] [--jobs 2]
            [--timeout 60] [--cases a,b,...] [--only ID,ID,...] [--keep]
            [--sweep KIND,KIND...]

Needs the environment of etc/bashrc (the project's solvers on PATH).
"""
import argparse
import collections
import json
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import threading
import time

PROJECT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
TUTORIALS = os.path.join(PROJECT, "tutorials")
PY = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable


# --------------------------------------------------------------------------
# Base cases: a tutorial, how it is prepared, how many steps are run
# --------------------------------------------------------------------------

def sub(path, pattern, repl, count=1, flags=re.M):
    """re.sub in a file; the pattern must match"""
    s = open(path).read()
    s, n = re.subn(pattern, repl, s, count=count, flags=flags)
    if n == 0:
        sys.exit("fuzz: pattern %r not found in %s" % (pattern, path))
    open(path, "w").write(s)


def prepTwoChargedSpheres(c):
    run(["blockMesh"], c)


def prepHeadOn(c):
    # 40 nm apart, closing at 1 m/s: in contact from the first step
    p = os.path.join(c, "constant/cloudProperties")
    sub(p, r"position \(-0\.55e-3 0 0\)", "position (-0.50002e-3 0 0)")
    sub(p, r"position \( 0\.55e-3 0 0\)", "position ( 0.50002e-3 0 0)")
    run(["blockMesh"], c)


def prepTribo(c):
    # 2.5 um above the plate at 2.56 m/s: contact in the first step
    sub(os.path.join(c, "constant/cloudProperties"),
        r"position \(0 0 1\.6695e-3\)", "position (0 0 1.5925e-3)")
    run(["blockMesh"], c)


def prepDrop(c):
    # each ellipsoid 20 um above the floor (its lowest point) at 0.5 m/s down
    import math
    p = os.path.join(c, "constant/cloudProperties")
    s = open(p).read()

    def lower(m):
        x, y, tilt = m.group(1), m.group(2), float(m.group(3))
        t = math.radians(tilt)
        h = math.hypot(1.5e-3*math.cos(t), 0.5e-3*math.sin(t))
        return ("{ position (%s %s %.6g); U (0 0 -0.5); semiAxes (1.5e-3 5e-4 5e-4); "
                "eulerAngles (0 %s 90);" % (x, y, h + 2e-5, m.group(3)))
    s, n = re.subn(r"\{ position \( *(\S+) (\S+) 4e-3\); semiAxes \(1\.5e-3 5e-4 5e-4\); "
                   r"eulerAngles \(0 (\d+) 90\);", lower, s)
    assert n == 4, n
    open(p, "w").write(s)
    run(["blockMesh"], c)


def prepGasSettling(c):
    run([PY, "makePositions.py", "--n", "40"], c)
    run(["blockMesh"], c)


def prepShortDuct(c):
    run([PY, os.path.join(TUTORIALS, "chargedDuct", "makeParcels.py"), "30", "1", "0.05"], c)
    run(["blockMesh"], c)


def prepAggregate(c):
    run(["blockMesh"], c)


# name: (tutorial, solver, steps, preparation)
CASES = collections.OrderedDict([
    ("twoChargedSpheres", ("twoChargedSpheres", "chargedParticleFoam", 5, prepTwoChargedSpheres)),
    ("dielectricSpheres", ("dielectricSpheres", "chargedParticleFoam", 5, prepTwoChargedSpheres)),
    ("headOnCollision", ("headOnCollision", "chargedParticleFoam", 10, prepHeadOn)),
    ("triboSingleContact", ("triboSingleContact", "chargedParticleFoam", 5, prepTribo)),
    ("ellipsoidDrop", ("ellipsoidDrop", "chargedParticleFoam", 5, prepDrop)),
    ("ellipsoidSettling", ("ellipsoidSettling", "chargedParticleFoam", 5, prepTwoChargedSpheres)),
    ("elasticEllipsoids", ("elasticEllipsoids", "chargedParticleFoam", 5, prepTwoChargedSpheres)),
    ("aggregateCollision", ("aggregateCollision", "chargedParticleFoam", 5, prepAggregate)),
    ("gasSettling", ("gasSettling", "chargedDPMFoam", 3, prepGasSettling)),
    ("shortDuct", ("shortDuct", "chargedDPMFoam", 3, prepShortDuct)),
])

FILES = ["constant/cloudProperties", "constant/parcels",
         "system/fvSolution", "constant/carrierProperties"]


def run(cmd, cwd, log=None, env=None, timeout=None):
    """run cmd in cwd (log: file for stdout+stderr); returns (rc, seconds);
    rc is 128 + signal for a signal, None for a timeout"""
    t0 = time.time()
    out = open(log, "w") if log else subprocess.DEVNULL
    try:
        p = subprocess.Popen(cmd, cwd=cwd, stdout=out, stderr=subprocess.STDOUT,
                             stdin=subprocess.DEVNULL, env=env, start_new_session=True)
        try:
            rc = p.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGKILL)
            p.wait()
            return None, time.time() - t0
    finally:
        if log:
            out.close()
    if rc < 0:
        rc = 128 - rc
    if log is None and rc != 0:
        sys.exit("fuzz: %s failed in %s (exit %s)" % (" ".join(cmd), cwd, rc))
    return rc, time.time() - t0


def setControl(case, steps):
    """run 'steps' time steps from the start, writing each"""
    p = os.path.join(case, "system/controlDict")
    s = open(p).read()
    dt = float(re.search(r"^deltaT\s+([^;]+);", s, re.M).group(1))
    t0 = float(re.search(r"^startTime\s+([^;]+);", s, re.M).group(1))
    for key, val in (("endTime", "%.12g" % (t0 + steps*dt)), ("writeControl", "timeStep"),
                     ("writeInterval", "1"), ("writeFormat", "ascii"),
                     ("writeCompression", "off"), ("stopAt", "endTime")):
        s, n = re.subn(r"^%s\s+[^;]*;" % key, "%-16s%s;" % (key, val), s, flags=re.M)
        if n == 0:
            s = s.replace("\nstartTime", "\n%-16s%s;\nstartTime" % (key, val), 1)
    open(p, "w").write(s)


# --------------------------------------------------------------------------
# A small OpenFOAM dictionary tokenizer and parser (spans into the text)
# --------------------------------------------------------------------------

TOKEN = re.compile(r"""
    (?P<ws>\s+)
  | (?P<lc>//[^\n]*)
  | (?P<bc>/\*.*?\*/)
  | (?P<str>"(?:[^"\\]|\\.)*")
  | (?P<punct>[{}();\[\]])
  | (?P<word>[^\s{}();"\[\]]+)
""", re.S | re.X)

NUMBER = re.compile(r"^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$")
BOOLS = {"true", "false", "yes", "no", "on", "off"}


def tokenize(text):
    toks = []
    for m in TOKEN.finditer(text):
        k = m.lastgroup
        if k in ("ws", "lc", "bc"):
            continue
        toks.append((m.group(), m.start(), m.end()))
    return toks


class Entry(object):
    """one dictionary entry: path, keyword span, value span, entry span"""

    def __init__(self, path, key, kspan, vspan, span, kind, vtoks):
        self.path, self.key = path, key
        self.kspan, self.vspan, self.span = kspan, vspan, span
        self.kind = kind            # dict | prim | item
        self.vtoks = vtoks          # value tokens (prim)
        self.inParcel = False
        self.vtype = self.valueType()

    def valueType(self):
        if self.kind == "dict":
            return "dict"
        if self.kind == "item":
            return "item"
        v = [t[0] for t in self.vtoks]
        if not v:
            return "flag"
        if len(v) == 1:
            w = v[0]
            if NUMBER.match(w):
                return "label" if re.match(r"^[-+]?\d+$", w) else "scalar"
            if w in BOOLS:
                return "bool"
            if w.startswith('"'):
                return "string"
            if w.startswith("$") or w.startswith("#"):
                return "other"
            return "word"
        if v[0] == "(" and v[-1] == ")":
            inner = v[1:-1]
            if "{" in inner:
                return "dictList"
            if inner and all(NUMBER.match(w) for w in inner):
                return "vector" if len(inner) == 3 else "numList"
            return "list"
        if any(NUMBER.match(w) for w in v):
            return "compound"
        return "other"

    def numericTokens(self):
        return [t for t in self.vtoks if NUMBER.match(t[0])]

    def name(self):
        return ".".join(self.path)


def parse(text):
    """entries of a dictionary text (nested dicts and lists of dicts)"""
    toks = tokenize(text)
    entries = []

    def body(i, path, inParcel, stop):
        nItem = 0
        while i < len(toks):
            t, s, e = toks[i]
            if t == stop:
                return i
            if t == ";":
                i += 1
                continue
            if t == "{":                # an anonymous dictionary (a list item)
                j = body(i + 1, path + ("[%d]" % nItem,), True, "}")
                ent = Entry(path + ("[%d]" % nItem,), "[%d]" % nItem, (s, e), (s, toks[j][2]),
                            (s, toks[j][2]), "item", [])
                ent.inParcel = True
                entries.append(ent)
                nItem += 1
                i = j + 1
                continue
            if t.startswith("#"):       # #include "file", #inputMode ...
                i += 2
                continue
            key = t
            kspan = (s, e)
            if i + 1 < len(toks) and toks[i + 1][0] == "{":
                j = body(i + 2, path + (key,), inParcel, "}")
                entries.append(Entry(path + (key,), key, kspan,
                                     (toks[i + 1][1], toks[j][2]), (s, toks[j][2]),
                                     "dict", []))
                ent = entries[-1]
                ent.inParcel = inParcel
                i = j + 1
                continue
            # primitive entry: tokens up to ';' at depth 0
            j = i + 1
            depth = 0
            while j < len(toks) and not (toks[j][0] == ";" and depth == 0):
                if toks[j][0] in "({":
                    depth += 1
                elif toks[j][0] in ")}":
                    depth -= 1
                    if depth < 0:
                        break
                j += 1
            vtoks = toks[i + 1:j]
            end = toks[j][2] if j < len(toks) and toks[j][0] == ";" else (
                vtoks[-1][2] if vtoks else e)
            vspan = (vtoks[0][1], vtoks[-1][2]) if vtoks else (e, e)
            ent = Entry(path + (key,), key, kspan, vspan, (s, end), "prim", vtoks)
            ent.inParcel = inParcel
            entries.append(ent)
            if ent.vtype == "dictList":     # parcels ( {...} {...} )
                k = i + 2
                n = 0
                while k < j - 1:
                    if toks[k][0] == "{":
                        q = body(k + 1, path + (key, "[%d]" % n), True, "}")
                        it = Entry(path + (key, "[%d]" % n), "[%d]" % n,
                                   (toks[k][1], toks[k][2]), (toks[k][1], toks[q][2]),
                                   (toks[k][1], toks[q][2]), "item", [])
                        it.inParcel = True
                        entries.append(it)
                        n += 1
                        k = q + 1
                    else:
                        k += 1
            i = j + 1
        return i

    body(0, (), False, None)
    return [e for e in entries if e.path[0] != "FoamFile"]


# --------------------------------------------------------------------------
# Mutations
# --------------------------------------------------------------------------

KINDS = ["delete", "wrongType", "negative", "zero", "huge", "tiny", "nan", "inf",
         "nanEval", "infEval", "unknownEntry", "renamed", "badWord"]

NUMERIC = {"scalar", "label", "vector", "numList", "compound"}


def typo(word, rng):
    """a misspelling of word (never word itself)"""
    letters = "abcdefghijklmnopqrstuvwxyz"
    for _ in range(20):
        w = list(word)
        op = rng.choice(["swap", "drop", "insert", "case", "change"])
        i = rng.randrange(len(w))
        if op == "swap" and len(w) > 1:
            i = min(i, len(w) - 2)
            w[i], w[i + 1] = w[i + 1], w[i]
        elif op == "drop" and len(w) > 1:
            del w[i]
        elif op == "insert":
            w.insert(i, rng.choice(letters))
        elif op == "case" and w[i].isalpha():
            w[i] = w[i].swapcase()
        else:
            w[i] = rng.choice(letters)
        t = "".join(w)
        if t != word and re.match(r"^[A-Za-z_]", t) and not re.search(r'["();{}\s]', t):
            return t
    return word + "x"


def applicable(kind, e):
    vt = e.vtype
    plainKey = re.match(r"^[A-Za-z_][A-Za-z0-9_.]*$", e.key) is not None
    if kind == "delete":
        return True
    if kind == "wrongType":
        return vt not in ("other",)
    if kind in ("negative", "zero", "huge", "tiny", "nan", "inf", "nanEval", "infEval"):
        return vt in NUMERIC and bool(e.numericTokens())
    if kind in ("unknownEntry", "renamed"):
        return plainKey and e.kind != "item"
    if kind == "badWord":
        return vt in ("word", "bool") or (vt == "compound" and any(
            re.match(r"^[A-Za-z]", t[0]) for t in e.vtoks))
    return False


NUMVALUE = {"zero": "0", "huge": "1e300", "tiny": "1e-200", "nan": "nan", "inf": "inf",
            "nanEval": "#eval{sqrt(-1)}", "infEval": "#eval{1e300*1e300}"}


def mutate(text, e, kind, rng):
    """the mutated text and a one-line description of the change"""
    def replace(span, new):
        return text[:span[0]] + new + text[span[1]:]
    old = text[e.vspan[0]:e.vspan[1]]
    if kind == "delete":
        return replace(e.span, ""), "deleted"
    if kind == "wrongType":
        vt = e.vtype
        choices = {
            "scalar": ["word", "vector", "dict", "string", "bool"],
            "label": ["word", "vector", "dict", "scalar"],
            "vector": ["scalar", "word", "vector2", "dict"],
            "numList": ["scalar", "word", "dict"],
            "compound": ["scalar", "word", "dict"],
            "word": ["scalar", "vector", "dict"],
            "string": ["scalar", "dict"],
            "bool": ["scalar", "word", "vector"],
            "dict": ["scalar", "word", "vector", "list"],
            "item": ["scalar", "word", "vector"],
            "dictList": ["scalar", "word", "dict"],
            "list": ["scalar", "word", "dict"],
            "flag": ["scalar", "word", "dict"],
        }[vt]
        new = {"word": "someWord", "vector": "(1 2 3)", "dict": "{ }", "string": '"text"',
               "bool": "true", "scalar": "0.5" if vt == "label" else "2", "vector2": "(1 2)",
               "list": "(a b)"}[rng.choice(choices)]
        if e.kind == "dict":
            if new == "{ }":
                new = "3"
            return replace(e.span, "%s %s;" % (e.key, new)), "%s -> %s" % ("{...}", new)
        if e.kind == "item":
            return replace(e.span, new), "{...} -> %s" % new
        if vt == "flag":
            return replace(e.span, "%s %s;" % (e.key, new)), "(no value) -> %s" % new
        return replace(e.vspan, new), "%s -> %s" % (old, new)
    if kind in NUMVALUE or kind == "negative":
        toks = e.numericTokens()
        nz = [t for t in toks if float(t[0]) != 0]
        t = rng.choice(nz if (kind == "negative" and nz) else toks)
        if kind == "negative":
            v = float(t[0])
            new = ("-" + t[0].lstrip("+-")) if v > 0 else ("-1" if v == 0 else t[0].lstrip("-"))
            if v < 0:   # already negative: make it a large negative one
                new = "-" + "%g" % (abs(v)*1e6)
        else:
            new = NUMVALUE[kind]
        s = text[:t[1]] + new + text[t[2]:]
        return s, "%s -> %s" % (old, s[e.vspan[0]:e.vspan[1] - (t[2] - t[1]) + len(new)])
    if kind == "unknownEntry":
        t = typo(e.key, rng)
        entryText = text[e.span[0]:e.span[1]]
        extra = t + entryText[len(e.key):]
        return (text[:e.span[1]] + "\n" + extra + text[e.span[1]:],
                "extra entry %s next to %s" % (t, e.key))
    if kind == "renamed":
        t = typo(e.key, rng)
        return replace(e.kspan, t), "renamed %s -> %s" % (e.key, t)
    if kind == "badWord":
        ws = [t for t in e.vtoks if re.match(r"^[A-Za-z]", t[0])]
        t = rng.choice(ws)
        new = "maybe" if t[0] in BOOLS else typo(t[0], rng)
        s = text[:t[1]] + new + text[t[2]:]
        return s, "%s -> %s" % (t[0], new)
    raise ValueError(kind)


# --------------------------------------------------------------------------
# Running and classifying
# --------------------------------------------------------------------------

NONFINITE = re.compile(r"(?<![A-Za-z_0-9.])[-+]?(nan|inf|infinity)(?![A-Za-z_0-9])", re.I)
SIGNS = ["Segmentation fault", "Floating point exception", "terminate called",
         "sigFpe", "sigSegv", "Aborted", "Bus error", "Illegal instruction",
         "sigAbrt", "sigBus", "sigIll"]
FATAL = re.compile(r"--> FOAM FATAL (IO )?ERROR")


def isTime(name):
    try:
        float(name)
        return True
    except ValueError:
        return False


def scanNonFinite(case, startTime):
    """files of the written time folders holding nan or inf"""
    bad = []
    for d in os.listdir(case):
        p = os.path.join(case, d)
        if not (os.path.isdir(p) and isTime(d)) or float(d) == startTime:
            continue
        for root, _, files in os.walk(p):
            for f in files:
                fp = os.path.join(root, f)
                try:
                    s = open(fp, errors="replace").read()
                except OSError:
                    continue
                # skip the header (FoamFile { ... })
                m = NONFINITE.search(s, s.find("}") + 1 if "FoamFile" in s else 0)
                if m:
                    bad.append("%s (%s)" % (os.path.relpath(fp, case), m.group()))
    return bad


def fatalMessage(log):
    m = FATAL.search(log)
    if not m:
        return ""
    msg = log[m.start():]
    end = re.search(r"\n(FOAM exiting|FOAM aborting)", msg)
    return msg[:end.start()] if end else msg[:3000]


def classify(rc, log, nonFinite):
    """class, detail"""
    msg = fatalMessage(log)
    if rc is None:
        return "hang", "timeout"
    if rc != 0 and msg:
        return "error", msg
    if rc != 0:     # a signal (>= 128) or a failure without a FOAM error
        sig = [s for s in SIGNS if s in log.replace("Floating point exception trapping", "")]
        return "crash", "exit %d%s" % (rc, (": " + sig[0]) if sig else "")
    if nonFinite:
        return "nan", ", ".join(nonFinite[:3])
    return "ran", ""


def briefMessage(msg):
    """the FOAM error message without its banner, on one line"""
    lines = [l.strip() for l in msg.splitlines()[1:] if l.strip()]
    text = " ".join(lines)
    return re.sub(r"\s+", " ", text)[:400]


def names(msg, m):
    """does the message name the entry ('named'), its file ('file'), neither?"""
    keys = {m["key"]}
    if m.get("typo"):
        keys.add(m["typo"])
    if m["kind"] == "badWord":     # the misspelt value names it too
        keys.add(m["what"].split(" -> ")[-1])
    body = msg
    for k in keys:
        if k.startswith("["):       # a whole parcel: 'parcel' or its index
            if re.search(r"parcel", body, re.I):
                return "named"
            continue
        k = k.strip('"')
        if re.search(r"(?<![A-Za-z0-9_])%s(?![A-Za-z0-9_])" % re.escape(k), body):
            return "named"
    base = os.path.basename(m["file"])
    if base in body or (base == "parcels" and "cloudProperties" in body):
        return "file"
    return "unnamed"


INVALID_ON_FACE = {"wrongType", "huge", "nan", "inf", "nanEval", "infEval"}

# signed by nature: a negative value is no error on its face
SIGNED = {"q", "Gamma", "U", "U0", "omega", "position", "eulerAngles", "quaternion",
          "pRefValue", "SOI", "appliedField", "poissonsRatio", "workFunction"}


def invalidOnFace(m):
    """a value no case should run with (negative: a positive scalar made
    negative, not a signed quantity or a vector component)"""
    if m["kind"] == "negative":
        return m["key"] not in SIGNED and m["vtype"] in ("scalar", "label") \
            and not m["what"].startswith("-")
    return m["kind"] in INVALID_ON_FACE


# --------------------------------------------------------------------------
# Driver
# --------------------------------------------------------------------------

def prepareBases(work, names_):
    bases = {}
    for name in names_:
        tut, solver, steps, prep = CASES[name]
        c = os.path.join(work, "base", name)
        ready = os.path.join(c, ".fuzzReady")
        if not os.path.exists(ready):
            shutil.rmtree(c, ignore_errors=True)
            shutil.copytree(os.path.join(TUTORIALS, tut), c,
                            ignore=shutil.ignore_patterns("runs", "log.*", "[1-9]*", "0.*",
                                                          "processor*", "*.png"))
            prep(c)
            setControl(c, steps)
            # the base case runs clean
            t = os.path.join(work, "base", name + ".check")
            shutil.rmtree(t, ignore_errors=True)
            shutil.copytree(c, t)
            rc, secs = run([solver], t, log=os.path.join(t, "log"), timeout=120)
            log = open(os.path.join(t, "log"), errors="replace").read()
            cls, detail = classify(rc, log, scanNonFinite(t, 0.0))
            if cls != "ran":
                sys.exit("fuzz: base case %s does not run clean (%s %s): see %s/log"
                         % (name, cls, detail[:200], t))
            open(ready, "w").write("%.2f\n" % secs)
            shutil.rmtree(t)
        secs = float(open(ready).read())
        files = {}
        for f in FILES:
            p = os.path.join(c, f)
            if os.path.exists(p):
                text = open(p).read()
                es = parse(text)
                if f == "constant/cloudProperties":
                    # its parcels are the 'parcels' file
                    files[f] = [e for e in es if not e.inParcel]
                    pe = [e for e in es if e.inParcel or e.key == "parcels"]
                    if any(e.inParcel for e in pe):
                        files["parcels:" + f] = pe
                elif f == "constant/parcels":
                    files["parcels:" + f] = es
                else:
                    files[f] = es
        bases[name] = dict(dir=c, solver=solver, steps=steps, secs=secs, files=files)
        print("fuzz: base %-20s %-20s %d steps, %.1f s, entries: %s" % (
            name, solver, steps, secs,
            ", ".join("%s %d" % (k.replace("constant/", "").replace("system/", ""), len(v))
                      for k, v in files.items())))
    return bases


def plan(bases, n, seed):
    """n mutations, seeded: base, file, entry, kind, new text"""
    rng = random.Random(seed)
    names_ = sorted(bases)
    out = []
    while len(out) < n:
        kind = rng.choice(KINDS)
        name = rng.choice(names_)
        b = bases[name]
        fkey = rng.choice(sorted(b["files"]))
        cands = [e for e in b["files"][fkey] if applicable(kind, e)]
        if not cands:
            continue
        e = rng.choice(cands)
        f = fkey.split(":", 1)[-1]
        text = open(os.path.join(b["dir"], f)).read()
        new, what = mutate(text, e, kind, rng)
        m = dict(id=len(out), base=name, file=f, group=fkey.split(":")[0] if ":" in fkey
                 else os.path.basename(f), entry=e.name(), key=e.key, vtype=e.vtype, kind=kind,
                 what=what, text=new)
        tm = re.search(r"(renamed \S+ -> |extra entry )(\S+)", what)
        if tm:
            m["typo"] = tm.group(2)
        out.append(m)
    return out


def planSweep(bases, kinds, seed):
    """every kind on every applicable entry (a parcel entry on the first
    parcel of each base only), seeded for the choice of component"""
    rng = random.Random(seed)
    out = []
    for name in sorted(bases):
        b = bases[name]
        for fkey in sorted(b["files"]):
            f = fkey.split(":", 1)[-1]
            text = open(os.path.join(b["dir"], f)).read()
            seen = set()
            for e in b["files"][fkey]:
                generic = re.sub(r"\[\d+\]", "[i]", e.name())
                if generic in seen:
                    continue
                seen.add(generic)
                for kind in kinds:
                    if not applicable(kind, e):
                        continue
                    new, what = mutate(text, e, kind, rng)
                    m = dict(id=len(out), base=name, file=f,
                             group=fkey.split(":")[0] if ":" in fkey else os.path.basename(f),
                             entry=e.name(), key=e.key, vtype=e.vtype, kind=kind, what=what,
                             text=new)
                    tm = re.search(r"(renamed \S+ -> |extra entry )(\S+)", what)
                    if tm:
                        m["typo"] = tm.group(2)
                    out.append(m)
    return out


def runOne(m, bases, work, timeout, keep):
    b = bases[m["base"]]
    c = os.path.join(work, "runs", "%04d" % m["id"])
    shutil.rmtree(c, ignore_errors=True)
    shutil.copytree(b["dir"], c)
    os.remove(os.path.join(c, ".fuzzReady"))
    open(os.path.join(c, m["file"]), "w").write(m["text"])
    env = dict(os.environ)
    if m["kind"] in ("nanEval", "infEval"):
        env["FOAM_SIGFPE"] = "false"
    logp = os.path.join(c, "log." + b["solver"])
    rc, secs = run([b["solver"]], c, log=logp, env=env, timeout=timeout)
    log = open(logp, errors="replace").read()
    cls, detail = classify(rc, log, scanNonFinite(c, 0.0) if rc == 0 else [])
    if cls == "ran" and re.search(r"^(Segmentation fault|terminate called|#\d+  Foam::sig)",
                                  log, re.M):
        cls, detail = "crash", "exit 0 after a signal's stack trace"
    res = dict(rc=rc, secs=secs, cls=cls)
    if cls == "error":
        res["named"] = names(detail, m)
        res["message"] = briefMessage(detail)
    else:
        res["message"] = detail
    res["nanLog"] = rc == 0 and bool(re.search(
        r"[=:]\s*[-+]?(nan|inf)\b", log, re.I))
    if cls == "ran":
        res["cls"] = "accepted" if invalidOnFace(m) else "ok"
    escape = res["cls"] in ("crash", "hang", "nan") or res.get("named") == "unnamed"
    res["escape"] = escape
    os.makedirs(os.path.join(work, "logs"), exist_ok=True)
    shutil.copy(logp, os.path.join(work, "logs", "%04d.log" % m["id"]))
    if not (escape or keep):
        shutil.rmtree(c, ignore_errors=True)
    return res


def report(muts, results, work, args, wall):
    cls = ["ok", "accepted", "error", "crash", "hang", "nan"]
    count = collections.Counter(r["cls"] for r in results.values())
    named = collections.Counter(r.get("named") for r in results.values()
                                if r["cls"] == "error")
    byKind = collections.defaultdict(collections.Counter)
    byFile = collections.defaultdict(collections.Counter)
    byBase = collections.defaultdict(collections.Counter)
    for m in muts:
        r = results.get(m["id"])
        if not r:
            continue
        byKind[m["kind"]][r["cls"]] += 1
        byFile[m["group"]][r["cls"]] += 1
        byBase[m["base"]][r["cls"]] += 1
        if r["cls"] == "error":
            byKind[m["kind"]]["named:" + r["named"]] += 1
            byFile[m["group"]]["named:" + r["named"]] += 1
            byBase[m["base"]]["named:" + r["named"]] += 1
    L = []
    L.append("# Dictionary fuzzing: %d mutations" % len(results))
    L.append("")
    L.append("`%s`, seed %d, %d jobs, timeout %g s; wall time %.0f s." % (
        " ".join(["fuzz.py"] + sys.argv[1:]), args.seed, args.jobs, args.timeout, wall))
    L.append("")
    L.append("Classes: ok (ran, nothing non-finite written), accepted (ran although the value "
             "is invalid on its face: wrong type, negative, huge, nan, inf), error (FOAM "
             "FATAL ERROR; named = the message names the entry, file = only its "
             "dictionary), crash, hang, nan (nan/inf written).")
    L.append("")

    def table(title, rows):
        L.append("| %s | n | ok | accepted | error | named | file | unnamed | crash | hang | nan |"
                 % title)
        L.append("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
        for k, c in rows:
            n = sum(c[x] for x in cls)
            L.append("| %s | %d | %s |" % (k, n, " | ".join(str(c[x]) for x in (
                "ok", "accepted", "error", "named:named", "named:file", "named:unnamed",
                "crash", "hang", "nan"))))
        L.append("")
    total = collections.Counter()
    for c in byKind.values():
        total.update(c)
    table("mutation", [(k, byKind[k]) for k in KINDS if k in byKind] + [("**all**", total)])
    table("file", sorted(byFile.items()))
    table("base case", sorted(byBase.items()))

    esc = [(m, results[m["id"]]) for m in muts if m["id"] in results
           and results[m["id"]]["escape"]]
    L.append("## Escapes (%d)" % len(esc))
    L.append("")
    if esc:
        L.append("| id | class | base | file | entry | mutation | result |")
        L.append("|---:|---|---|---|---|---|---|")
        for m, r in esc:
            L.append("| %d | %s | %s | %s | `%s` | %s: `%s` | %s |" % (
                m["id"], r["cls"] if r["cls"] != "error" else "unnamed error", m["base"],
                m["file"], m["entry"], m["kind"], m["what"].replace("|", "\\|"),
                r["message"][:200].replace("|", "\\|")))
        L.append("")
        L.append("Rerun one (its case is kept in %s/runs/ID): `fuzz.py --seed %d %s "
                 "--only ID`" % (work, args.seed, ("--sweep " + args.sweep) if args.sweep
                                 else "--n %d" % args.n))
    else:
        L.append("None.")
    L.append("")

    nl = [(m, results[m["id"]]) for m in muts if m["id"] in results
          and results[m["id"]].get("nanLog") and not results[m["id"]]["escape"]]
    if nl:
        L.append("## nan or inf printed in the log, none written (%d)" % len(nl))
        L.append("")
        for m, r in nl[:40]:
            L.append("- %d %s %s `%s` %s: `%s`" % (m["id"], m["base"], m["file"], m["entry"],
                                                  m["kind"], m["what"]))
        L.append("")

    # accepted, grouped by entry and kind (most suspicious first: parcel and
    # model entries with a non-finite or negative value)
    acc = collections.defaultdict(list)
    for m in muts:
        r = results.get(m["id"])
        if r and r["cls"] == "accepted":
            generic = re.sub(r"\[\d+\]", "[i]", m["entry"])
            acc[(m["group"], generic)].append(m)
    rank = {"nanEval": 0, "infEval": 0, "negative": 1, "wrongType": 2, "huge": 3,
            "nan": 4, "inf": 4}
    L.append("## Accepted (%d runs, %d entries): ran although invalid on its face" % (
        sum(len(v) for v in acc.values()), len(acc)))
    L.append("")
    L.append("| file | entry | mutations |")
    L.append("|---|---|---|")
    for (g, ent), ms in sorted(acc.items(), key=lambda kv: (
            min(rank.get(m["kind"], 5) for m in kv[1]), kv[0])):
        L.append("| %s | `%s` | %s |" % (g, ent, "; ".join(
            "%s `%s` (%s)" % (m["kind"], m["what"][:60].replace("|", "\\|"), m["base"])
            for m in ms[:3]) + (" ..." if len(ms) > 3 else "")))
    L.append("")

    # named-by-file and examples of error messages per kind
    L.append("## Errors naming only the file (%d)" % named["file"])
    L.append("")
    for m in muts:
        r = results.get(m["id"])
        if r and r["cls"] == "error" and r["named"] == "file":
            L.append("- %d %s `%s` %s `%s`: %s" % (m["id"], m["base"], m["entry"], m["kind"],
                                                  m["what"][:60], r["message"][:200]))
    L.append("")

    open(os.path.join(work, "fuzz.md"), "w").write("\n".join(L) + "\n")
    with open(os.path.join(work, "results.json"), "w") as f:
        json.dump([dict({k: v for k, v in m.items() if k != "text"}, **results[m["id"]])
                   for m in muts if m["id"] in results], f, indent=1)
    nErr = count["error"]
    return ("fuzz: %d mutations: %d ok, %d accepted, %d errors (%d naming the entry, "
            "%d the file only, %d unnamed), %d crashes, %d hangs, %d NaN written"
            % (len(results), count["ok"], count["accepted"], nErr, named["named"],
               named["file"], named["unnamed"], count["crash"], count["hang"], count["nan"]))


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--n", type=int, default=1000, help="mutations (default 1000)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--work", default="/tmp/fuzz")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--timeout", type=float, default=60)
    ap.add_argument("--cases", default=",".join(CASES),
                    help="base cases (default all: %s)" % ",".join(CASES))
    ap.add_argument("--only", default="", help="run only these mutation ids (kept)")
    ap.add_argument("--sweep", default="",
                    help="instead of N random mutations: these kinds (comma-separated)"
                    " on every applicable entry of every base case")
    ap.add_argument("--keep", action="store_true", help="keep every mutated case")
    ap.add_argument("--fresh", action="store_true", help="prepare the base cases again")
    args = ap.parse_args()

    for s in ("chargedParticleFoam", "chargedDPMFoam", "blockMesh"):
        if not shutil.which(s):
            sys.exit("fuzz: %s not found: source etc/bashrc and build (./Allwmake)" % s)
    work = os.path.abspath(args.work)
    os.makedirs(work, exist_ok=True)
    if args.fresh:
        shutil.rmtree(os.path.join(work, "base"), ignore_errors=True)
    names_ = [c for c in args.cases.split(",") if c]
    for c in names_:
        if c not in CASES:
            sys.exit("fuzz: unknown case %s (%s)" % (c, ", ".join(CASES)))
    t0 = time.time()
    bases = prepareBases(work, names_)
    if args.sweep:
        kinds = args.sweep.split(",")
        for k in kinds:
            if k not in KINDS:
                sys.exit("fuzz: unknown mutation %s (%s)" % (k, ", ".join(KINDS)))
        muts = planSweep(bases, kinds, args.seed)
        args.n = len(muts)
    else:
        muts = plan(bases, args.n, args.seed)
    todo = muts
    if args.only:
        ids = {int(x) for x in args.only.split(",")}
        todo = [m for m in muts if m["id"] in ids]
        args.keep = True
    else:
        shutil.rmtree(os.path.join(work, "runs"), ignore_errors=True)
        shutil.rmtree(os.path.join(work, "logs"), ignore_errors=True)

    results = {}
    lock = threading.Lock()
    queue = list(reversed(todo))
    done = [0]

    def worker():
        while True:
            with lock:
                if not queue:
                    return
                m = queue.pop()
            r = runOne(m, bases, work, args.timeout, args.keep)
            with lock:
                results[m["id"]] = r
                done[0] += 1
                if r["escape"] or args.only:
                    print("  %4d %-8s %s %s %s %s: %s -> %s" % (
                        m["id"], r["cls"] + ("/" + r["named"] if "named" in r else ""),
                        m["base"], m["file"], m["entry"], m["kind"], m["what"][:80],
                        r["message"][:160]), flush=True)
                if done[0] % 50 == 0:
                    print("fuzz: %d/%d done, %.0f s" % (done[0], len(todo), time.time() - t0),
                          flush=True)

    threads = [threading.Thread(target=worker) for _ in range(max(1, args.jobs))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    line = report(muts, results, work, args, time.time() - t0)
    print("fuzz: report in %s/fuzz.md, %.0f s" % (work, time.time() - t0))
    print(line)


if __name__ == "__main__":
    main()
