/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "OscillatingFrameForce.H"
#include "mathematicalConstants.H"
#include "checkedEntry.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::OscillatingFrameForce<CloudType>::OscillatingFrameForce
(
    CloudType& owner,
    const fvMesh& mesh,
    const dictionary& dict
)
:
    ParticleForce<CloudType>(owner, mesh, dict, typeName, true),
    amplitude_
    (
        getChecked<vector>
        (
            this->coeffs(), "amplitude",
            [](const vector& a) { return std::isfinite(mag(a)); },
            ": it must be finite [m]"
        )
    ),
    frequency_
    (
        getPositive
        (
            this->coeffs(), "frequency",
            std::numeric_limits<scalar>::max(), " [Hz]"
        )
    ),
    acceleration_(Zero)
{
    const scalar dt = mesh.time().deltaTValue();
    Info<< "    Oscillating frame: amplitude " << amplitude_ << " m, "
        << frequency_ << " Hz, peak acceleration "
        << sqr(constant::mathematical::twoPi*frequency_)*mag(amplitude_)
        << " m/s^2" << endl;
    if (frequency_*dt > 0.05)
    {
        WarningInFunction
            << "deltaT = " << dt << " s resolves the period 1/f = "
            << 1/frequency_ << " s with fewer than 20 steps" << endl;
    }
}


template<class CloudType>
Foam::OscillatingFrameForce<CloudType>::OscillatingFrameForce
(
    const OscillatingFrameForce& of
)
:
    ParticleForce<CloudType>(of),
    amplitude_(of.amplitude_),
    frequency_(of.frequency_),
    acceleration_(of.acceleration_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class CloudType>
Foam::vector Foam::OscillatingFrameForce<CloudType>::frameAcceleration
(
    const scalar t
) const
{
    const scalar omega = constant::mathematical::twoPi*frequency_;
    return -sqr(omega)*std::sin(omega*t)*amplitude_;
}


template<class CloudType>
void Foam::OscillatingFrameForce<CloudType>::cacheFields(const bool store)
{
    if (store)
    {
        const Time& time = this->mesh().time();
        acceleration_ =
            frameAcceleration(time.value() - 0.5*time.deltaTValue());
    }
}


template<class CloudType>
Foam::forceSuSp Foam::OscillatingFrameForce<CloudType>::calcNonCoupled
(
    const typename CloudType::parcelType& p,
    const typename CloudType::parcelType::trackingData& td,
    const scalar dt,
    const scalar mass,
    const scalar Re,
    const scalar muc
) const
{
    forceSuSp value(Zero);
    value.Su() = -mass*acceleration_;
    return value;
}


// ************************************************************************* //
