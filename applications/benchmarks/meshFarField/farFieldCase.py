#!/usr/bin/env python3
"""Build, run and read a one-step electrostatics case for chargedParticleFoam.

A box [0,L]^3 of n^3 hexahedra holds point charges at rest (heavy parcels,
one tiny time step, so the written parcel fields E and fE are those of the
input positions). The walls are one patch `walls`: grounded (type wall) or
tri-periodic (three cyclic pairs). Used by the meshFarField test and
benchmark (study.py) to compare the electrostatics models with an exact
reference (tests/tools/groundedBox.py, or Ewald for the periodic box).

    case = FarFieldCase(path, x, q, L, n, model, coeffs, periodic=False)
    case.run(nProcs=1)          -> seconds of the force evaluations
    case.fields()               -> (E, fE) ordered as the input charges
"""
import os
import re
import shutil
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
TOP = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
sys.path.insert(0, os.path.join(TOP, "etc", "python"))
from foamLagrangian import read_field, read_positions  # noqa: E402

HEADER = """FoamFile
{
    version     2.0;
    format      ascii;
    class       %s;
    object      %s;
}
"""


# Electrodes: x = 0 at 0 V (patch left), x = L at `right` V, insulating
# sides; pass as FarFieldCase(..., boundary=ELECTRODES, Phi=electrodesPhi(V))
ELECTRODES = """
    left  { type wall; faces ((0 4 7 3)); }
    right { type wall; faces ((1 2 6 5)); }
    sides { type patch; faces ((0 1 5 4) (3 7 6 2) (0 3 2 1) (4 5 6 7)); }"""


def electrodesPhi(right):
    return """    left  { type fixedValue; value uniform 0; }
    right { type fixedValue; value uniform %r; }
    sides { type zeroGradient; }""" % right


def _write(path, obj, body, cls="dictionary"):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(HEADER % (cls, obj) + body)


class FarFieldCase:
    def __init__(self, path, x, q, L, n, model, coeffs="", periodic=False,
                 steps=1, solver="PCG", tol=1e-12, boundary=None, Phi=None,
                 d=1e-6, parcelEntries="", blockMesh=None):
        self.path, self.x, self.q = path, np.asarray(x), np.asarray(q)
        self.L, self.n, self.model = L, n, model
        self.coeffs, self.periodic, self.steps = coeffs, periodic, steps
        self.solver, self.tol = solver, tol
        # optional: blockMeshDict boundary entries and a 0/Phi
        # boundaryField body (default: the walls/cyclics and no 0/Phi)
        self.boundary, self.Phi = boundary, Phi
        # parcel diameter and further entries of every parcel (e.g. epsilonR)
        self.d, self.parcelEntries = d, parcelEntries
        # optional: a whole blockMeshDict body (another geometry: L, n and
        # boundary are then unused)
        self.blockMesh = blockMesh

    def write(self):
        p = self.path
        # L, n: scalars (a cube) or 3-vectors (a box)
        L = np.broadcast_to(np.asarray(self.L, dtype=float), (3,))
        n = np.broadcast_to(np.asarray(self.n, dtype=int), (3,))
        shutil.rmtree(p, ignore_errors=True)
        if self.boundary:
            patches = self.boundary
        elif self.periodic:
            patches = """
    x0 { type cyclic; neighbourPatch x1; faces ((0 4 7 3)); }
    x1 { type cyclic; neighbourPatch x0; faces ((1 2 6 5)); }
    y0 { type cyclic; neighbourPatch y1; faces ((0 1 5 4)); }
    y1 { type cyclic; neighbourPatch y0; faces ((3 7 6 2)); }
    z0 { type cyclic; neighbourPatch z1; faces ((0 3 2 1)); }
    z1 { type cyclic; neighbourPatch z0; faces ((4 5 6 7)); }"""
        else:
            patches = """
    walls
    {
        type wall;
        faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2) (0 3 2 1) (4 5 6 7));
    }"""
        if self.blockMesh:
            _write(p + "/system/blockMeshDict", "blockMeshDict", self.blockMesh)
        else:
            _write(p + "/system/blockMeshDict", "blockMeshDict", f"""
scale 1;
vertices ((0 0 0) ({L[0]!r} 0 0) ({L[0]!r} {L[1]!r} 0) (0 {L[1]!r} 0)
    (0 0 {L[2]!r}) ({L[0]!r} 0 {L[2]!r}) ({L[0]!r} {L[1]!r} {L[2]!r})
    (0 {L[1]!r} {L[2]!r}));
blocks (hex (0 1 2 3 4 5 6 7) ({n[0]} {n[1]} {n[2]}) simpleGrading (1 1 1));
boundary
({patches}
);
""")
        if self.Phi:
            _write(p + "/0/Phi", "Phi", f"""
dimensions [1 2 -3 0 0 -1 0];
internalField uniform 0;
boundaryField
{{
{self.Phi}
}}
""", cls="volScalarField")
        dt = 1e-9
        _write(p + "/system/controlDict", "controlDict", f"""
application chargedParticleFoam;
startFrom startTime; startTime 0; stopAt endTime;
endTime {dt*self.steps!r}; deltaT {dt!r};
writeControl timeStep; writeInterval {self.steps};
purgeWrite 0; writeFormat ascii; writePrecision 17;
writeCompression off; timeFormat general; timePrecision 8;
runTimeModifiable false;
""")
        os.makedirs(p + "/0", exist_ok=True)
        _write(p + "/system/fvSchemes", "fvSchemes", """
ddtSchemes { default none; }
gradSchemes { default Gauss linear; }
divSchemes { default none; }
laplacianSchemes { default Gauss linear corrected; }
interpolationSchemes { default linear; }
snGradSchemes { default corrected; }
""")
        pre = "DIC" if self.solver == "PCG" else "none"
        solver = (f"solver PCG; preconditioner {pre};" if self.solver == "PCG"
                  else "solver GAMG; smoother GaussSeidel;")
        _write(p + "/system/fvSolution", "fvSolution", f"""
solvers {{ Phi {{ {solver} tolerance {self.tol!r}; relTol 0; }} }}
""")
        _write(p + "/constant/g", "g", """
dimensions [0 1 -2 0 0 0 0];
value (0 0 0);
""")
        parcels = "\n".join(
            "            { position (%.17g %.17g %.17g); U (0 0 0); d %.17g; "
            "rho 1e20; q %.17g; %s }" % (a[0], a[1], a[2], self.d, c, self.parcelEntries)
            for a, c in zip(self.x, self.q))
        _write(p + "/constant/cloudProperties", "cloudProperties", f"""
solution
{{
    active true; coupled false; transient yes;
    cellValueSourceCorrection off; maxCo 0.3;
    interpolationSchemes {{ rho.carrier cell; U.carrier cell; mu.carrier cell; }}
    integrationSchemes {{ U Euler; }}
    sourceTerms {{ schemes {{}} }}
}}
constantProperties {{ rho0 1e20; }}
subModels
{{
    particleForces {{}}
    electrostaticsModel {self.model};
    {self.model}Coeffs {{ {self.coeffs} }}
    injectionModels
    {{
        charges
        {{
            type explicitParcels;
            SOI 0;
            parcels
            (
{parcels}
            );
        }}
    }}
    collisionModel none;
    dispersionModel none;
    patchInteractionModel standardWallInteraction;
    standardWallInteractionCoeffs {{ type rebound; e 1; mu 0; }}
    stochasticCollisionModel none;
    surfaceFilmModel none;
}}
cloudFunctions {{}}
""")

    def _sh(self, cmd, log):
        with open(os.path.join(self.path, "log." + log), "w") as f:
            r = subprocess.run(cmd, cwd=self.path, stdout=f,
                               stderr=subprocess.STDOUT, shell=True)
        if r.returncode:
            raise RuntimeError(f"{cmd} failed in {self.path} (see log.{log})")

    def run(self, nProcs=1):
        """Write and run the case; return the solver's wall time [s]."""
        self.write()
        self._sh("blockMesh", "blockMesh")
        t0 = time.time()
        if nProcs > 1:
            # simple: halves along x, then y, then z (2, 4, 8 processors)
            split = {2: "2 1 1", 4: "2 2 1", 8: "2 2 2"}.get(nProcs, f"{nProcs} 1 1")
            _write(self.path + "/system/decomposeParDict", "decomposeParDict", f"""
numberOfSubdomains {nProcs};
method simple;
coeffs {{ n ({split}); }}
""")
            self._sh("decomposePar -force", "decomposePar")
            self._sh(f"mpirun -np {nProcs} chargedParticleFoam -parallel",
                     "chargedParticleFoam")
            t1 = time.time()
            self._sh("reconstructPar -latestTime", "reconstructPar")
        else:
            self._sh("chargedParticleFoam", "chargedParticleFoam")
            t1 = time.time()
        return t1 - t0

    def fields(self):
        """Parcel E and fE of the last time, ordered as the input charges."""
        times = [d for d in os.listdir(self.path)
                 if re.fullmatch(r"[0-9.e+-]+", d) and float(d) > 0]
        t = max(times, key=float)
        c = f"{self.path}/{t}/lagrangian/cloud"
        xs = read_positions(c + "/positions")
        E = read_field(c + "/E").reshape(-1, 3)
        fE = read_field(c + "/fE").reshape(-1, 3)
        idx = [int(np.argmin(np.linalg.norm(self.x - xi, axis=1)))
               for xi in xs]
        if sorted(idx) != list(range(len(self.x))):
            raise RuntimeError(f"{self.path}: parcels lost or not matched")
        Eo = np.zeros_like(self.x)
        fo = np.zeros_like(self.x)
        Eo[idx], fo[idx] = E, fE
        return Eo, fo

    def log(self):
        with open(os.path.join(self.path, "log.chargedParticleFoam")) as f:
            return f.read()
