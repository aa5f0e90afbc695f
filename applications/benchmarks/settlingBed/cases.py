"""Case writers of the settling-bed benchmark: one function per code fills a
case directory from templates/ (placeholders @@NAME@@) and the lattice of
physics.py, and the readers of the final states.

Codes (keys of CODES):
  cfSpheres        chargedParticleFoam, spheres, ellipsoidCollision
  cfEllipsoids     chargedParticleFoam, prolate ellipsoids (aspect ratio 2)
  cfPairCollision  chargedParticleFoam, spheres, OpenFOAM's pairCollision
  ofIco            icoUncoupledKinematicParcelFoam (Debian), pairCollision
  liggghts         LIGGGHTS (Debian), hertz + tangential history
"""
import math
import os
import re
import shutil

import numpy as np

import physics as ph

HERE = os.path.dirname(os.path.abspath(__file__))
TEMPLATES = os.path.join(HERE, "templates")

CODES = {
    "cfSpheres": "chargedFoam, spheres, ellipsoidCollision (sphere fast path)",
    "cfEllipsoids": "chargedFoam, ellipsoids AR 2, ellipsoidCollision",
    "cfPairCollision": "chargedFoam, spheres, OpenFOAM pairCollision in our cloud",
    "ofIco": "icoUncoupledKinematicParcelFoam (Debian), pairCollision",
    "liggghts": "LIGGGHTS 3.8 (Debian), hertz + tangential history",
}

# OpenFOAM header of files written here
FOAM_HEADER = """/*--------------------------------*- C++ -*----------------------------------*\\
  chargedFoam benchmark settlingBed (written by settlingBed.py)
\\*---------------------------------------------------------------------------*/
FoamFile
{{
    version     2.0;
    format      ascii;
    class       {cls};
    location    "{loc}";
    object      {obj};
}}
// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

"""


def fmt(x):
    """Number for an input file (12 significant digits)."""
    return f"{float(x):.12g}"


def fill(text, values):
    def rep(m):
        key = m.group(1)
        if key not in values:
            raise KeyError(f"template placeholder @@{key}@@ has no value")
        return str(values[key])
    return re.sub(r"@@([A-Z0-9_]+)@@", rep, text)


def copy_template(src, dst, values):
    os.makedirs(os.path.dirname(dst), exist_ok=True)
    with open(src) as f:
        text = f.read()
    with open(dst, "w") as f:
        f.write(fill(text, values))


class State:
    """Particle state: centres x, velocities U, angular velocities omega
    (inertial frame) and, for ellipsoids, orientations q (w x y z)."""

    def __init__(self, x, U, omega=None, q=None, shape="sphere"):
        self.x = np.asarray(x, float)
        self.U = np.asarray(U, float)
        self.omega = np.zeros_like(self.x) if omega is None else np.asarray(omega, float)
        self.q = q
        self.shape = shape

    @property
    def n(self):
        return len(self.x)

    @classmethod
    def lattice(cls, n, base, shape="sphere", seed=1):
        spacing = ph.SPACING_SPHERE if shape == "sphere" else ph.SPACING_ELLIPSOID
        x, U, q = ph.lattice(n, spacing, base, seed=seed)
        return cls(x, U, q=q if shape == "ellipsoid" else None, shape=shape)

    @classmethod
    def from_liggghts_dump(cls, path):
        """State of a dump 'id x y z vx vy vz omegax omegay omegaz' (sorted by id)."""
        with open(path) as f:
            lines = f.read().splitlines()
        i = lines.index(next(l for l in lines if l.startswith("ITEM: ATOMS")))
        a = np.array([l.split() for l in lines[i + 1:] if l.strip()], float)
        a = a[np.argsort(a[:, 0])]
        return cls(a[:, 1:4], a[:, 4:7], a[:, 7:10])


class Setup:
    """One run: state, number of steps, DEM time step, box height."""

    def __init__(self, state, nsteps, dt, base, lz, vmax, cell):
        self.state = state
        self.base = base
        self.cell = cell
        self.n = state.n
        self.shape = state.shape
        self.nsteps = nsteps
        self.dt = dt
        self.lz = lz
        self.vmax = vmax
        self.beta = ph.damping_ratio_cached(ph.REST)

    @property
    def end_time(self):
        return self.nsteps*self.dt

    def values(self):
        dmax = 2*max(ph.SEMI_AXES_ELLIPSOID) if self.shape == "ellipsoid" else ph.D
        ofres, cfres = self.resolution_steps()
        return {
            "LX": fmt(self.base), "LY": fmt(self.base), "LZ": fmt(self.lz), "CELL": fmt(self.cell),
            "NX": self.ncells(self.base), "NY": self.ncells(self.base), "NZ": self.ncells(self.lz),
            "NSTEPS": self.nsteps, "DELTAT": fmt(self.dt),
            "ENDTIME": f"{self.end_time:.12g}",
            "G": fmt(ph.G), "RHO": fmt(ph.RHO), "E": fmt(ph.E), "NU": fmt(ph.NU),
            "REST": fmt(ph.REST), "MU": fmt(ph.MU), "BETA": f"{self.beta:.15g}",
            "ALPHA": f"{math.sqrt(5)*abs(self.beta):.15g}",
            "RESTL": f"{ph.liggghts_restitution(self.beta):.15g}",
            "DMAX": fmt(dmax*1.05), "NPARCELS": self.n,
            "OFRESOLUTION": ofres, "CFRESOLUTION": cfres,
            "DELTABLRATIO": 0 if self.shape == "sphere" else ph.DELTABL_RATIO_ELLIPSOID,
            "SKIN": fmt(0.25*ph.D), "THERMO": max(1, self.nsteps//20),
        }

    def ncells(self, length):
        return max(1, round(length/self.cell))

    def resolution_steps(self):
        """(OpenFOAM, chargedFoam) collisionResolutionSteps: see
        physics.resolution_steps."""
        return ph.resolution_steps(self.dt, self.vmax)


# ----------------------------------------------------------------------------
# OpenFOAM cases

def write_openfoam_common(case, s, application):
    v = s.values()
    v["APPLICATION"] = application
    t = os.path.join(TEMPLATES, "openfoam")
    for f in ("system/blockMeshDict", "system/controlDict", "system/fvSchemes",
              "system/fvSolution", "constant/g"):
        copy_template(os.path.join(t, f), os.path.join(case, f), v)
    return v


def collision_block(kind, v):
    with open(os.path.join(TEMPLATES, "openfoam", "constant", kind + ".inc")) as f:
        return fill(f.read(), v)


def write_chargedfoam(case, s, collision):
    """chargedParticleFoam case; collision: ellipsoidCollision | pairCollision."""
    v = write_openfoam_common(case, s, "chargedParticleFoam")
    v["UNAME"] = "U.carrier"
    v["COLLISION"] = collision_block(collision, v)
    copy_template(os.path.join(TEMPLATES, "openfoam", "constant", "cloudProperties"),
                  os.path.join(case, "constant", "cloudProperties"), v)
    st = s.state
    lines = []
    for i in range(st.n):
        x, U, w = st.x[i], st.U[i], st.omega[i]
        if st.shape == "sphere":
            size = f"d {ph.D:g};"
            orient = ""
            # body frame = inertial frame (identity orientation)
            omega = f" omega ({w[0]:.15e} {w[1]:.15e} {w[2]:.15e});" if w.any() else ""
        else:
            a = ph.SEMI_AXES_ELLIPSOID
            q = st.q[i]
            size = f"semiAxes ({a[0]:g} {a[1]:g} {a[2]:g});"
            orient = f" quaternion ({q[0]:.15f} {q[1]:.15f} {q[2]:.15f} {q[3]:.15f});"
            if w.any():
                raise ValueError("ellipsoids start without rotation")
            omega = ""
        lines.append(f"    {{ position ({x[0]:.15e} {x[1]:.15e} {x[2]:.15e}); "
                     f"U ({U[0]:.15e} {U[1]:.15e} {U[2]:.15e}); {size}{orient}{omega} q 0; }}")
    with open(os.path.join(case, "constant", "parcels"), "w") as f:
        f.write("// Written by settlingBed.py: lattice positions, random velocities\n"
                "parcels\n(\n" + "\n".join(lines) + "\n);\n")


def write_ico(case, s):
    """icoUncoupledKinematicParcelFoam case; the parcels are the initial
    state of the cloud in 0/lagrangian/kinematicCloud (legacy 'positions'
    with the owner cell of the block mesh, which the reader relocates)."""
    v = write_openfoam_common(case, s, "icoUncoupledKinematicParcelFoam")
    v["UNAME"] = "U"
    v["COLLISION"] = collision_block("pairCollision", v)
    t = os.path.join(TEMPLATES, "openfoam")
    for f in ("constant/kinematicCloudProperties", "constant/transportProperties",
              "constant/turbulenceProperties", "0/U"):
        copy_template(os.path.join(t, f), os.path.join(case, f), v)

    lag = os.path.join(case, "0", "lagrangian", "kinematicCloud")
    os.makedirs(lag, exist_ok=True)
    st = s.state
    n = st.n
    nx, ny, nz = v["NX"], v["NY"], v["NZ"]
    h = np.array([s.base/nx, s.base/ny, s.lz/nz])
    ijk = np.clip(np.floor(st.x/h).astype(int), 0, [nx - 1, ny - 1, nz - 1])
    cell = ijk[:, 0] + nx*(ijk[:, 1] + ny*ijk[:, 2])

    def write(name, cls, body):
        with open(os.path.join(lag, name), "w") as f:
            f.write(FOAM_HEADER.format(cls=cls, loc="0/lagrangian/kinematicCloud", obj=name))
            f.write(body)
            f.write("\n\n// ************************************************************************* //\n")

    # Legacy 'positions' mode, and the count the particle ids continue from
    uni = os.path.join(case, "0", "uniform", "lagrangian", "kinematicCloud")
    os.makedirs(uni)
    with open(os.path.join(uni, "cloudProperties"), "w") as f:
        f.write(FOAM_HEADER.format(cls="dictionary", loc="0/uniform/lagrangian/kinematicCloud",
                                   obj="cloudProperties"))
        f.write(f"geometry positions;\n\nprocessor0\n{{\n    particleCount {n};\n}}\n")

    pos = "\n".join(f"({p[0]:.15e} {p[1]:.15e} {p[2]:.15e}) {c}" for p, c in zip(st.x, cell))
    write("positions", "Cloud<basicKinematicCollidingParcel>", f"{n}\n(\n{pos}\n)")

    def labels(val):
        return f"{n}{{{val}}}"

    def scalars(val):
        return f"{n}{{{val!r}}}"

    vec0 = f"{n}{{(0 0 0)}}"
    write("origProcId", "labelField", labels(0))
    write("origId", "labelField", f"{n}\n(\n" + "\n".join(str(i) for i in range(n)) + "\n)")
    write("active", "labelField", labels(1))
    write("typeId", "labelField", labels(-1))
    write("nParticle", "scalarField", scalars(1.0))
    write("d", "scalarField", scalars(ph.D))
    write("dTarget", "scalarField", scalars(0.0))
    write("rho", "scalarField", scalars(ph.RHO))
    write("age", "scalarField", scalars(0.0))
    write("tTurb", "scalarField", scalars(0.0))
    write("U", "vectorField",
          f"{n}\n(\n" + "\n".join(f"({u[0]:.15e} {u[1]:.15e} {u[2]:.15e})" for u in st.U) + "\n)")
    # Angular momentum of a solid sphere: I omega, I = m d^2/10
    L = 0.1*ph.mass_sphere()*ph.D**2*st.omega
    write("angularMomentum", "vectorField",
          f"{n}\n(\n" + "\n".join(f"({l[0]:.15e} {l[1]:.15e} {l[2]:.15e})" for l in L) + "\n)")
    for name in ("UTurb", "f", "torque"):
        write(name, "vectorField", vec0)
    # Collision records: none (compact format: n + 1 offsets, no values)
    for name in ("collisionRecordsPairAccessed", "collisionRecordsPairOrigProcOfOther",
                 "collisionRecordsPairOrigIdOfOther", "collisionRecordsWallAccessed"):
        write(name, "labelFieldCompactField", f"{n + 1}{{0}}\n0()")
    for name in ("collisionRecordsPairData", "collisionRecordsWallPRel",
                 "collisionRecordsWallData"):
        write(name, "vectorFieldCompactField", f"{n + 1}{{0}}\n0()")


# ----------------------------------------------------------------------------
# LIGGGHTS case

def write_liggghts(case, s):
    v = s.values()
    os.makedirs(case, exist_ok=True)
    copy_template(os.path.join(TEMPLATES, "liggghts", "in.settlingBed"),
                  os.path.join(case, "in.settlingBed"), v)
    st = s.state
    n = st.n
    with open(os.path.join(case, "data.lattice"), "w") as f:
        f.write("LIGGGHTS data file: settlingBed lattice (written by settlingBed.py)\n\n")
        f.write(f"{n} atoms\n1 atom types\n\n")
        f.write(f"0 {v['LX']} xlo xhi\n0 {v['LY']} ylo yhi\n0 {v['LZ']} zlo zhi\n\n")
        f.write("Atoms\n\n")
        for i, p in enumerate(st.x):
            f.write(f"{i + 1} 1 {ph.D:g} {ph.RHO:g} {p[0]:.15e} {p[1]:.15e} {p[2]:.15e}\n")
        f.write("\nVelocities\n\n")
        for i, (u, w) in enumerate(zip(st.U, st.omega)):
            f.write(f"{i + 1} {u[0]:.15e} {u[1]:.15e} {u[2]:.15e} {w[0]:.15e} {w[1]:.15e} {w[2]:.15e}\n")


def write_case(code, case, s):
    if os.path.isdir(case):
        shutil.rmtree(case)
    os.makedirs(case)
    if code == "cfSpheres" or code == "cfEllipsoids":
        write_chargedfoam(case, s, "ellipsoidCollision")
    elif code == "cfPairCollision":
        write_chargedfoam(case, s, "pairCollision")
    elif code == "ofIco":
        write_ico(case, s)
    elif code == "liggghts":
        write_liggghts(case, s)
    else:
        raise ValueError(code)


def _sub(path, pattern, repl):
    with open(path) as f:
        text = f.read()
    new, n = re.subn(pattern, repl, text, flags=re.M)
    if n == 0:
        raise ValueError(f"{path}: no match for {pattern}")
    with open(path, "w") as f:
        f.write(new)


def set_resolution(case, steps):
    """collisionResolutionSteps of a chargedFoam case."""
    _sub(os.path.join(case, "constant", "cloudProperties"),
         r"^(\s*collisionResolutionSteps\s+)\S+;", rf"\g<1>{steps};")


def set_window(case, t0, nsteps, dt, resolution):
    """Restart a chargedFoam case from its latest time t0 for nsteps steps
    of dt, writing the last one."""
    cd = os.path.join(case, "system", "controlDict")
    _sub(cd, r"^startFrom\s+\S+;", "startFrom       latestTime;")
    _sub(cd, r"^endTime\s+\S+;", f"endTime         {t0 + nsteps*dt:.12g};")
    _sub(cd, r"^deltaT\s+\S+;", f"deltaT          {fmt(dt)};")
    _sub(cd, r"^writeControl\s+\S+;", "writeControl    runTime;")
    _sub(cd, r"^writeInterval\s+\S+;", f"writeInterval   {nsteps*dt:.12g};")
    set_resolution(case, resolution)
