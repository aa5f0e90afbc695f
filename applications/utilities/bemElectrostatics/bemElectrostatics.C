/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
-------------------------------------------------------------------------------
Application
    bemElectrostatics

Description
    Static electrostatics of charged dielectric ellipsoids: surface-resolved
    BEM (Ruan 2022, Eqs. 7-12) and/or the monopole + induced-dipole model
    (Eqs. 45-48), for a configuration read from a dictionary and swept over
    translations or rotations of one particle. Writes

        <outputDir>/<model>.dat   step value, energy [, interaction energy],
                                  per particle F (Eq. 11a) and M (Eq. 11b),
                                  GMRES iterations and residual
        <outputDir>/surface_<step>.vtk   legacy-VTK surfaces with sigma_f,
                                  sigma_b, sigma = sigma_f + sigma_b and the
                                  particle index per patch (ParaView)

    Input: -dict <file>, default system/bemElectrostaticsDict of the case.
    Example: applications/utilities/bemElectrostatics/bemElectrostaticsDict.example

\*---------------------------------------------------------------------------*/

#include "readUtilityDict.H"
#include "argList.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "dictionary.H"
#include "bemSolver.H"
#include "pairwiseCoulomb.H"
#include "inducedDipole.H"
#include "rigidBodyRotation.H"
#include "unitConversion.H"
#include "quaternion.H"

using namespace Foam;

namespace
{

struct particleSpec
{
    word name;
    point centre;
    tensor R;
    vector semiAxes;
    scalar kappa;
    bool hasCharge;
    scalar charge;
    scalar sigmaF;
    label nPatches;
    scalar lambda;
    vector focus;
    scalar beta;
};


tensor readOrientation(const dictionary& pd)
{
    if (!pd.found("orientation"))
    {
        return tensor::I;
    }
    const dictionary& od = pd.subDict("orientation");
    const word type = od.get<word>("type");
    if (type == "euler")
    {
        // Ruan Eq. 17: z-x-z angles (phi, theta, psi) in degrees
        const vector ang = od.get<vector>("angles");
        return rigidBodyRotation::fromEulerAngles
        (
            degToRad(ang.x()), degToRad(ang.y()), degToRad(ang.z())
        ).R();
    }
    else if (type == "quaternion")
    {
        // (w x y z), normalised here
        const FixedList<scalar, 4> q = od.get<FixedList<scalar, 4>>("q");
        quaternion Q(q[0], vector(q[1], q[2], q[3]));
        const scalar m = Foam::sqrt(magSqr(Q.w()) + magSqr(Q.v()));
        if (!(m > 0))
        {
            FatalIOErrorInFunction(od)
                << "quaternion q must be non-zero" << exit(FatalIOError);
        }
        return quaternion(Q.w()/m, Q.v()/m).R();
    }
    FatalIOErrorInFunction(od)
        << "orientation type " << type << " unknown; allowed: euler"
        << " (angles (phi theta psi) [deg], z-x-z) or quaternion"
        << " (q (w x y z))" << exit(FatalIOError);
    return tensor::I;
}


particleSpec readParticle(const word& name, const dictionary& pd)
{
    particleSpec p;
    p.name = name;
    p.centre = pd.get<point>("centre");
    p.R = readOrientation(pd);
    p.semiAxes = pd.get<vector>("semiAxes");
    if (cmptMin(p.semiAxes) <= 0)
    {
        FatalIOErrorInFunction(pd)
            << "semiAxes " << p.semiAxes << " of " << name
            << " must all be > 0" << exit(FatalIOError);
    }
    p.kappa = pd.get<scalar>("kappa");
    if (!(p.kappa >= 1))
    {
        FatalIOErrorInFunction(pd)
            << "kappa " << p.kappa << " of " << name << " must be >= 1"
            << exit(FatalIOError);
    }
    p.hasCharge = pd.found("charge");
    p.charge = pd.getOrDefault<scalar>("charge", 0);
    p.sigmaF = pd.getOrDefault<scalar>("sigmaF", 0);
    if (p.hasCharge && pd.found("sigmaF"))
    {
        FatalIOErrorInFunction(pd)
            << "give either charge [C] or sigmaF [C/m^2] for " << name
            << ", not both" << exit(FatalIOError);
    }
    p.nPatches = pd.getOrDefault<label>("nPatches", 800);
    if (p.nPatches < 8 || p.nPatches > 200000)
    {
        FatalIOErrorInFunction(pd)
            << "nPatches " << p.nPatches << " of " << name
            << " out of range [8, 200000]" << exit(FatalIOError);
    }
    p.beta = pd.getOrDefault<scalar>("curvatureGrading", 0);
    if (!(p.beta >= 0 && p.beta <= 1))
    {
        FatalIOErrorInFunction(pd)
            << "curvatureGrading " << p.beta << " of " << name
            << " out of range [0, 1] (patch size ~ H^-beta)"
            << exit(FatalIOError);
    }
    p.lambda = 1;
    p.focus = vector(1, 0, 0);
    if (pd.found("grading"))
    {
        const dictionary& gd = pd.subDict("grading");
        p.lambda = gd.get<scalar>("lambda");
        p.focus = gd.get<vector>("focus");
        if (!(p.lambda > 0 && p.lambda <= 1) || mag(p.focus) == 0)
        {
            FatalIOErrorInFunction(gd)
                << "grading lambda " << p.lambda << " out of range (0, 1]"
                << " or zero focus " << p.focus << exit(FatalIOError);
        }
    }
    return p;
}


tensor rotationAbout(const vector& axis, const scalar angleDeg)
{
    const scalar a = degToRad(angleDeg);
    return quaternion(axis/mag(axis), a).R();
}


void writeVtk
(
    const fileName& file,
    const bemSolver& s
)
{
    OFstream os(file);
    os.precision(10);
    label nPts = 0, nTri = 0;
    for (label p = 0; p < s.nParticles(); ++p)
    {
        nPts += s.vertices(p).size();
        nTri += s.sigmaF(p).size();
    }
    os  << "# vtk DataFile Version 3.0" << nl
        << "bemElectrostatics surface charge" << nl
        << "ASCII" << nl
        << "DATASET POLYDATA" << nl
        << "POINTS " << nPts << " double" << nl;
    labelList base(s.nParticles());
    label off = 0;
    for (label p = 0; p < s.nParticles(); ++p)
    {
        base[p] = off;
        for (const point& x : s.vertices(p))
        {
            os << x.x() << ' ' << x.y() << ' ' << x.z() << nl;
        }
        off += s.vertices(p).size();
    }
    os  << "POLYGONS " << nTri << ' ' << 4*nTri << nl;
    for (label p = 0; p < s.nParticles(); ++p)
    {
        for (const auto& f : s.faces(p))
        {
            os  << "3 " << base[p] + f[0] << ' ' << base[p] + f[1] << ' '
                << base[p] + f[2] << nl;
        }
    }
    os  << "CELL_DATA " << nTri << nl;
    const char* names[3] = {"sigmaF", "sigmaB", "sigma"};
    for (label k = 0; k < 3; ++k)
    {
        os  << "SCALARS " << names[k] << " double 1" << nl
            << "LOOKUP_TABLE default" << nl;
        for (label p = 0; p < s.nParticles(); ++p)
        {
            const scalarField& sf = s.sigmaF(p);
            const auto sb = s.sigmaB(p);
            forAll(sf, i)
            {
                os  << (k == 0 ? sf[i] : k == 1 ? sb[i] : sf[i] + sb[i])
                    << nl;
            }
        }
    }
    os  << "SCALARS particle int 1" << nl << "LOOKUP_TABLE default" << nl;
    for (label p = 0; p < s.nParticles(); ++p)
    {
        forAll(s.sigmaF(p), i)
        {
            os << p << nl;
        }
    }
}

//- What the dictionary asks for
struct caseSpec
{
    scalar kappa0 = 1;
    vector E0 = Zero;
    bemSolverControls ctrl;
    bool interaction = true;
    bool vtk = true;
    fileName outDir;
    List<particleSpec> parts;
    word sweepType = "none";
    label sweepP = -1;
    vector sweepDir = Zero;
    scalarList values = scalarList(1, 0.0);
};


//- The particles of the dictionary's particles sub-dictionary
List<particleSpec> readParticles(const dictionary& dict)
{
    List<particleSpec> parts;
    const dictionary& pdict = dict.subDict("particles");
    for (const entry& e : pdict)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(pdict)
                << "entry " << e.keyword() << " of particles is not a"
                << " dictionary" << exit(FatalIOError);
        }
        parts.append(readParticle(e.keyword(), e.dict()));
    }
    if (parts.empty())
    {
        FatalIOErrorInFunction(pdict) << "no particles" << exit(FatalIOError);
    }

    return parts;
}


//- The sweep (sub-dictionary sweep; none: one configuration) into cs
void readSweep(const dictionary& dict, caseSpec& cs)
{
    const List<particleSpec>& parts = cs.parts;
    word& sweepType = cs.sweepType;
    label& sweepP = cs.sweepP;
    vector& sweepDir = cs.sweepDir;
    scalarList& values = cs.values;
    if (dict.found("sweep"))
    {
        const dictionary& sd = dict.subDict("sweep");
        sweepType = sd.get<word>("type");
        if (sweepType != "none")
        {
            const word pn = sd.get<word>("particle");
            forAll(parts, i)
            {
                if (parts[i].name == pn) sweepP = i;
            }
            if (sweepP < 0)
            {
                FatalIOErrorInFunction(sd)
                    << "sweep particle " << pn << " not in particles"
                    << exit(FatalIOError);
            }
            values = sd.get<scalarList>("values");
            if (sweepType == "translate")
            {
                sweepDir = sd.get<vector>("direction");
            }
            else if (sweepType == "rotate")
            {
                sweepDir = sd.get<vector>("axis");
            }
            else
            {
                FatalIOErrorInFunction(sd)
                    << "sweep type " << sweepType << " unknown; allowed:"
                    << " none translate (value = displacement along"
                    << " direction) rotate (value = angle [deg] about axis)"
                    << exit(FatalIOError);
            }
            if (mag(sweepDir) == 0)
            {
                FatalIOErrorInFunction(sd)
                    << "zero sweep direction/axis" << exit(FatalIOError);
            }
        }
    }

}


//- One configuration (centres c, rotations R) by the model: forces,
//  torques, energy and interaction energy, GMRES iterations and residual
//  (the BEM's surface written to surface_<step>.vtk if vtk)
void evaluateStep
(
    const word& model,
    const caseSpec& cs,
    bemSolver& bem,
    const labelList& shapes,
    const scalarList& charge,
    const scalar Uself,
    const List<point>& c,
    const List<tensor>& R,
    const label step,
    List<vector>& F,
    List<vector>& M,
    scalar& U,
    scalar& Uint,
    label& iters,
    scalar& resid
)
{
    const List<particleSpec>& parts = cs.parts;
    const scalar kappa0 = cs.kappa0;
    const vector& E0 = cs.E0;
    const bool interaction = cs.interaction;
    F.setSize(parts.size());
    M.setSize(parts.size());
    U = 0;
    Uint = 0;
    iters = 0;
    resid = 0;
    if (model == "bem")
    {
        bem.clearParticles();
        forAll(parts, i)
        {
            bem.addParticle(shapes[i], c[i], R[i], parts[i].kappa, charge[i]);
        }
        if (mag(E0) > 0)
        {
            bem.setExternalField(E0);
        }
        const auto& info = bem.solve();
        F = bem.forces();
        M = bem.torques();
        U = bem.energy();
        Uint = interaction ? U - Uself : 0;
        iters = info.iterations;
        resid = info.residual;
        if (cs.vtk)
        {
            writeVtk
            (
                cs.outDir/("surface_" + Foam::name(step) + ".vtk"), bem
            );
        }
    }
    else
    {
        inducedDipole dm(kappa0);
        forAll(parts, i)
        {
            dm.addParticle(c[i], parts[i].semiAxes, R[i], parts[i].kappa, charge[i]);
        }
        dm.setExternalField(E0);
        iters = dm.solve();
        F = dm.forces();
        M = dm.torques();
        U = dm.energy();
        Uint = U;
    }
}


//- The sweep by one model, its table to <outputDir>/<model>.dat
void runModel(const word& model, const caseSpec& cs)
{
    const List<particleSpec>& parts = cs.parts;
    const scalar kappa0 = cs.kappa0;
    const bool interaction = cs.interaction;
    const word& sweepType = cs.sweepType;
    const label sweepP = cs.sweepP;
    const vector& sweepDir = cs.sweepDir;
    const scalarList& values = cs.values;
    const fileName& outDir = cs.outDir;
    const bemSolverControls& ctrl = cs.ctrl;
    const scalar eps0 = pairwiseCoulomb::vacuumPermittivity;

    bemSolver bem(kappa0, ctrl);
    labelList shapes(parts.size());
    scalarList charge(parts.size());
    forAll(parts, i)
    {
        const particleSpec& p = parts[i];
        shapes[i] =
            bem.shape(p.semiAxes, p.nPatches, p.focus, p.lambda, p.beta);
        const scalar A = sum(bem.mesh(shapes[i]).areas());
        charge[i] = p.hasCharge ? p.charge : p.sigmaF*A;
    }

    // Energies of the particles alone (same mesh), for the interaction
    // energy U - sum U_i
    scalar Uself = 0;
    if (interaction && model == "bem")
    {
        forAll(parts, i)
        {
            bemSolver one(kappa0, ctrl);
            const label sh = one.shape
            (
                parts[i].semiAxes, parts[i].nPatches, parts[i].focus,
                parts[i].lambda, parts[i].beta
            );
            one.addParticle(sh, parts[i].centre, parts[i].R, parts[i].kappa, charge[i]);
            one.solve();
            Uself += one.energy();
        }
    }

    OFstream tab(outDir/(model + ".dat"));
    tab.precision(17);
    tab << "# bemElectrostatics, model " << model << ", kappa0 "
        << kappa0 << ", eps0 " << eps0 << nl
        << "# sweep " << sweepType
        << (sweepP >= 0 ? (" of " + parts[sweepP].name).c_str() : "")
        << nl << "# columns: step value energy[J] interactionEnergy[J]";
    forAll(parts, i)
    {
        tab << " " << parts[i].name << ":Fx Fy Fz Mx My Mz";
    }
    tab << " iterations residual" << nl;

    Info<< "Model " << model << ": writing " << outDir/(model + ".dat")
        << nl;

    forAll(values, step)
    {
        List<point> c(parts.size());
        List<tensor> R(parts.size());
        forAll(parts, i)
        {
            c[i] = parts[i].centre;
            R[i] = parts[i].R;
        }
        if (sweepType == "translate")
        {
            c[sweepP] += values[step]*sweepDir/mag(sweepDir);
        }
        else if (sweepType == "rotate")
        {
            R[sweepP] = rotationAbout(sweepDir, values[step]) & R[sweepP];
        }

        List<vector> F, M;
        scalar U, Uint, resid;
        label iters;
        evaluateStep
        (
            model, cs, bem, shapes, charge, Uself, c, R, step,
            F, M, U, Uint, iters, resid
        );

        tab << step << ' ' << values[step] << ' ' << U << ' ' << Uint;
        forAll(parts, i)
        {
            tab << ' ' << F[i].x() << ' ' << F[i].y() << ' ' << F[i].z()
                << ' ' << M[i].x() << ' ' << M[i].y() << ' ' << M[i].z();
        }
        tab << ' ' << iters << ' ' << resid << nl;

        Info<< "  step " << step << " value " << values[step]
            << "  U " << U << "  F[" << parts.last().name << "] "
            << F.last() << "  M[" << parts.last().name << "] "
            << M.last() << "  iterations " << iters << nl;
    }
}


} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Forces, torques and energy of charged dielectric ellipsoids by BEM"
        " (Ruan 2022, Eqs. 7-12) and/or the induced-dipole model (Eqs."
        " 45-48), swept over separations or rotations."
    );
    argList::noParallel();
    argList::noFunctionObjects();
    addUtilityDictOption("bemElectrostatics");

    argList args(argc, argv);

    fileName dictFile;
    const dictionary dict(readUtilityDict(args, "bemElectrostatics", dictFile));

    const scalar kappa0 = dict.getOrDefault<scalar>("kappa0", 1);
    if (!(kappa0 >= 1))
    {
        FatalIOErrorInFunction(dict)
            << "kappa0 " << kappa0 << " must be >= 1" << exit(FatalIOError);
    }
    const vector E0 = dict.getOrDefault<vector>("externalField", Zero);
    const bemSolverControls ctrl =
        bemSolverControls::read(dict.subOrEmptyDict("solver"));
    const wordList models =
        dict.getOrDefault<wordList>("models", wordList({"bem"}));
    for (const word& m : models)
    {
        if (m != "bem" && m != "inducedDipole")
        {
            FatalIOErrorInFunction(dict)
                << "model " << m << " unknown; allowed: bem inducedDipole"
                << exit(FatalIOError);
        }
    }
    const bool interaction = dict.getOrDefault<bool>("interactionEnergy", true);
    const bool vtk = dict.getOrDefault<bool>("writeVtk", true);
    // outputDir: relative to the case, or absolute as given
    fileName outDir
    (
        dict.getOrDefault<fileName>
        (
            "outputDir", "postProcessing/bemElectrostatics"
        ).expand()
    );
    if (!outDir.isAbsolute())
    {
        outDir = args.path()/outDir;
    }
    mkDir(outDir);

    caseSpec cs;
    cs.kappa0 = kappa0;
    cs.E0 = E0;
    cs.ctrl = ctrl;
    cs.interaction = interaction;
    cs.vtk = vtk;
    cs.outDir = outDir;
    cs.parts = readParticles(dict);
    readSweep(dict, cs);

    for (const word& model : models)
    {
        runModel(model, cs);
    }

    Info<< "End" << nl;
    return 0;
}


// ************************************************************************* //
