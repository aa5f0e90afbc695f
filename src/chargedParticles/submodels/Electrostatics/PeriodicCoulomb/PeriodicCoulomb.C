/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "PeriodicCoulomb.H"
#include "cyclicPolyPatch.H"
#include "processorHalo.H"
#include "checkedEntry.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
Foam::dictionary Foam::PeriodicCoulomb<CloudType>::kernelDict
(
    const dictionary& coeffs,
    const CloudType& owner
)
{
    dictionary d(coeffs);
    if (!d.found("method"))
    {
        d.add("method", word("p3m"));
    }
    if (!d.found("L"))
    {
        // The periodic box is the mesh (cyclic in x, y and z)
        d.add("L", owner.mesh().bounds().span());
    }

    label nCyclic = 0;
    for (const polyPatch& pp : owner.mesh().boundaryMesh())
    {
        if (isA<cyclicPolyPatch>(pp))
        {
            ++nCyclic;
        }
    }
    if (nCyclic < 6)
    {
        WarningInFunction
            << "electrostaticsModel periodic: the mesh has " << nCyclic
            << " cyclic patches; the forces are those of a tri-periodic box"
            << " of edges " << d.get<vector>("L") << endl;
    }
    return d;
}


template<class CloudType>
void Foam::PeriodicCoulomb<CloudType>::reportTimeStep() const
{
    const Time& time = this->owner().mesh().time();
    if (time.timeIndex() % 100 != 1 && time.timeIndex() > 1)
    {
        return;
    }

    // Cloud means (all processors): |q|, m
    scalar n = 0, sumQ = 0, sumM = 0;
    for (const auto& p : this->owner())
    {
        n += 1;
        sumQ += mag(p.q());
        sumM += p.mass();
    }
    reduce(n, sumOp<scalar>());
    reduce(sumQ, sumOp<scalar>());
    reduce(sumM, sumOp<scalar>());
    if (n == 0 || sumQ == 0)
    {
        return;
    }

    const scalar Q = sumQ/n, m = sumM/n;
    const scalar density = n/cmptProduct(kernel_->L());
    const scalar k = kernel_->k();
    // The larger of the measured agitation and the stationary estimate
    // of Eq. (25) (the smaller time step: the cloud starts at rest)
    const scalar qp2Measured = this->owner().agitation();
    const scalar qp2Estimate =
        coulombCollision::agitationEstimate(k, Q, m, density);
    const bool measured = qp2Measured >= qp2Estimate;
    const scalar qp2 = max(qp2Measured, qp2Estimate);
    const scalar w = coulombCollision::meanRelativeSpeed(qp2);
    const scalar dC = coulombCollision::diameter(k, Q, Q, m, m, w);
    const scalar dtMax = coulombCollision::maxTimeStep(dC, w);
    const scalar dt = time.deltaTValue();

    Info<< "    Coulomb collisions (Boutsikakis 2023): q_p^2 = " << qp2
        << (measured ? " (measured)" : " (Eq. 25 estimate; measured "
          + Foam::name(qp2Measured) + ")").c_str()
        << " m2/s2, d_C = " << dC
        << " m, tau_el = " << coulombCollision::tauEl(k, Q, m, density)
        << " s; Eq. 23 time step " << dtMax << " s (deltaT " << dt << " s)"
        << endl;
    if (dt > dtMax)
    {
        WarningInFunction
            << "deltaT = " << dt << " s exceeds the Coulomb-collision time"
            << " step " << dtMax << " s of Boutsikakis 2023 Eq. 23: close"
            << " approaches are not resolved" << endl;
    }
}


template<class CloudType>
Foam::label Foam::PeriodicCoulomb<CloudType>::readPotentialInterval
(
    const dictionary& coeffs
)
{
    return getCheckedOrDefault<label>
    (
        coeffs, "potentialInterval", 0,
        [](const label n) { return n >= 0; },
        " [0, inf) (0: no potential statistics)"
    );
}


template<class CloudType>
void Foam::PeriodicCoulomb<CloudType>::reportPotentials
(
    const UList<point>& x,
    const UList<scalar>& q
) const
{
    scalarField phi;
    kernel_->potentialsDistributed
    (
        x, q, processorHalo::processorBoxes(this->owner().mesh()), phi
    );
    // Two passes: the mean may be far larger than the spread (direct,
    // Nper > 1: it grows as Nper^2)
    scalar n = phi.size(), s = sum(phi);
    reduce(n, sumOp<scalar>());
    reduce(s, sumOp<scalar>());
    if (n > 0)
    {
        const scalar mean = s/n;
        scalar s2 = sumSqr(phi - mean);
        reduce(s2, sumOp<scalar>());
        Info<< "    Potential at the charges <phi>_p = " << mean
            << " V, <phi'^2>_p = " << s2/n << " V2" << endl;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::PeriodicCoulomb<CloudType>::PeriodicCoulomb
(
    const dictionary& dict,
    CloudType& owner
)
:
    ElectrostaticsModel<CloudType>(dict, owner, typeName),
    kernelDict_(kernelDict(this->coeffDict(), owner)),
    kernel_(periodicElectrostatics::New(kernelDict_)),
    infoWritten_(false),
    potentialInterval_(readPotentialInterval(this->coeffDict()))
{
    if (potentialInterval_ > 0 && !kernel_->hasPotentials())
    {
        FatalIOErrorInFunction(this->coeffDict())
            << "Entry potentialInterval = " << potentialInterval_
            << ": method " << kernel_->method() << " gives no potentials"
            << " (p3m and direct do; 0 switches the statistics off)"
            << exit(FatalIOError);
    }

    const scalar chi = owner.constProps().stiffnessRatio();
    if (chi != 1)
    {
        FatalIOErrorInFunction(owner.constProps().dict())
            << "Entry stiffnessRatio = " << chi << " < 1 (reduced stiffness,"
            << " Ruan Eq. 44) is not supported by electrostaticsModel "
            << typeName << ": use 1 or directCoulomb" << exit(FatalIOError);
    }

    Info<< "    Tri-periodic electrostatics: ";
    kernel_->writeInfo(Info);
    Info<< endl;
}


template<class CloudType>
Foam::PeriodicCoulomb<CloudType>::PeriodicCoulomb
(
    const PeriodicCoulomb<CloudType>& em
)
:
    ElectrostaticsModel<CloudType>(em),
    kernelDict_(em.kernelDict_),
    kernel_(periodicElectrostatics::New(kernelDict_)),
    infoWritten_(false),
    potentialInterval_(em.potentialInterval_)
{}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

template<class CloudType>
void Foam::PeriodicCoulomb<CloudType>::calculate()
{
    reportTimeStep();

    // This processor's parcels: the kernel exchanges what it needs
    pointField x(this->owner().size());
    scalarField q(x.size());
    label i = 0;
    for (const auto& p : this->owner())
    {
        x[i] = p.centre();
        q[i] = p.q();
        ++i;
    }

    List<vector> f;
    kernel_->computeDistributed
    (
        x, q, processorHalo::processorBoxes(this->owner().mesh()), f
    );
    if (!infoWritten_)
    {
        infoWritten_ = true;
        // The parameters chosen for the run's first step (and, in parallel,
        // what the master holds)
        Info<< "    ";
        kernel_->writeInfo(Info);
        Info<< endl;
    }

    const label step = this->owner().mesh().time().timeIndex();
    if (potentialInterval_ > 0 && step % potentialInterval_ == 0)
    {
        reportPotentials(x, q);
    }

    i = 0;
    for (auto& p : this->owner())
    {
        p.fE() = f[i];
        p.E() = p.q() != 0 ? f[i]/p.q() : vector::zero;
        ++i;
    }
}


template<class CloudType>
Foam::scalar Foam::PeriodicCoulomb<CloudType>::energy() const
{
    const ewaldSum* ewald = dynamic_cast<const ewaldSum*>(kernel_.get());
    if (!ewald)
    {
        return 0;
    }

    pointField x;
    scalarField q;
    label offset = 0;
    this->gatherCharges(x, q, offset);

    return ewald->energy(x, q);
}


// ************************************************************************* //
