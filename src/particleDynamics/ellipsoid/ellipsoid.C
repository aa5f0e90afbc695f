/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "ellipsoid.H"
#include "rigidBodyRotation.H"
#include "error.H"
#include "Ostream.H"
#include "mathematicalConstants.H"
#include <algorithm>
#include <tr1/cmath>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using namespace Foam;

bool finite(const vector& v)
{
    return
        std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}

// Body-frame point scaled along its ray onto the surface
vector ontoSurface(const vector& xb, const vector& ax, const char* caller)
{
    const scalar s2 =
        sqr(xb.x()/ax.x()) + sqr(xb.y()/ax.y()) + sqr(xb.z()/ax.z());
    if (!(s2 > 0) || !std::isfinite(s2))
    {
        FatalErrorInFunction
            << caller << ": the point (body frame " << xb
            << ") is the centre of the ellipsoid or not finite;"
            << " a surface point is needed" << exit(FatalError);
    }
    return xb/Foam::sqrt(s2);
}

} // End anonymous namespace


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::ellipsoid::init(const bool checkRotation)
{
    if
    (
        !finite(semiAxes_)
     || !(semiAxes_.x() > 0) || !(semiAxes_.y() > 0) || !(semiAxes_.z() > 0)
    )
    {
        FatalErrorInFunction
            << "Ellipsoid semi-axes " << semiAxes_
            << " are invalid: all three must be finite and > 0"
            << exit(FatalError);
    }

    if (!finite(centre_))
    {
        FatalErrorInFunction
            << "Ellipsoid centre " << centre_ << " is not finite"
            << exit(FatalError);
    }

    // Proper orthogonal to 1e-9: a tensor off by more is not a rotation
    // (e.g. built from an unnormalised quaternion), and the contact would
    // silently use a distorted shape. A rotation from a normalised
    // quaternion is one to round-off: not checked (the test is a third
    // of the construction, and the contact model builds a shell per
    // parcel and step)
    if (checkRotation)
    {
        const tensor E = (R_ & R_.T()) - tensor::I;
        scalar err = 0;
        for (direction i = 0; i < tensor::nComponents; ++i)
        {
            if (!std::isfinite(R_[i]))
            {
                err = GREAT;
            }
            err = max(err, mag(E[i]));
        }
        if (!(err < 1e-9) || !(det(R_) > 0))
        {
            FatalErrorInFunction
                << "Ellipsoid rotation tensor " << R_
                << " is not a rotation: |R R^T - I| = " << err
                << ", det R = " << det(R_) << " (need R R^T = I, det R = 1)"
                << exit(FatalError);
        }
    }

    const vector& ax = semiAxes_;
    S_ = rigidBodyRotation::rotateDiagonal
    (
        R_,
        vector(1/sqr(ax.x()), 1/sqr(ax.y()), 1/sqr(ax.z()))
    );
    Sinv_ = rigidBodyRotation::rotateDiagonal(R_, cmptMultiply(ax, ax));
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::ellipsoid::ellipsoid
(
    const vector& semiAxes,
    const point& centre,
    const tensor& R
)
:
    semiAxes_(semiAxes),
    centre_(centre),
    R_(R)
{
    init(true);
}


Foam::ellipsoid::ellipsoid
(
    const vector& semiAxes,
    const point& centre,
    const quaternion& q
)
:
    semiAxes_(semiAxes),
    centre_(centre),
    R_(rotation(q))
{
    init(false);
}


Foam::ellipsoid::ellipsoid(const scalar radius, const point& centre)
:
    semiAxes_(radius, radius, radius),
    centre_(centre),
    R_(tensor::I)
{
    init(false);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tensor Foam::ellipsoid::rotation(const quaternion& q)
{
    const scalar m2 = sqr(q.w()) + magSqr(q.v());
    if (!(m2 > 0) || !std::isfinite(m2))
    {
        FatalErrorInFunction
            << "Ellipsoid orientation quaternion " << q
            << " is zero or not finite" << exit(FatalError);
    }

    // Within 1e-8 of a unit quaternion (a parcel's, renormalised by every
    // rotation step): 1/|q| by a Newton step for 1/sqrt, whose error
    // 3/8 (|q|^2 - 1)^2 is below round-off, without the square root and
    // the divisions (a shell per parcel and step); any other by |q|
    if (mag(m2 - 1) < 1e-8)
    {
        const scalar s = 0.5*(3 - m2);
        return quaternion(s*q.w(), s*q.v()).R();
    }
    const scalar m = Foam::sqrt(m2);
    return quaternion(q.w()/m, q.v()/m).R();
}


Foam::scalar Foam::ellipsoid::surfaceArea(const vector& semiAxes)
{
    // a >= b >= c; S = 2 pi c^2 + 2 pi a b/sin(phi) (E(phi, k) sin^2 phi
    // + F(phi, k) cos^2 phi), cos phi = c/a, k^2 = a^2 (b^2 - c^2)/(b^2
    // (a^2 - c^2)) (Legendre; DLMF 19.33.2). Elliptic integrals from
    // libstdc++'s TR1 special functions (C++11 has no std:: ones)
    // Clouds mostly hold one shape and call this per parcel and step
    // (drag, charging): remember the last answer (per thread)
    static thread_local vector lastAxes(Zero);
    static thread_local scalar lastArea(0);
    if (semiAxes == lastAxes)
    {
        return lastArea;
    }

    scalar s[3] = {semiAxes.x(), semiAxes.y(), semiAxes.z()};
    std::sort(s, s + 3);
    const scalar a = s[2], b = s[1], c = s[0];
    const scalar pi = constant::mathematical::pi;

    if (!(c > 0))
    {
        FatalErrorInFunction
            << "Semi-axes " << semiAxes << " must be > 0" << exit(FatalError);
    }
    if (a - c <= 1e-12*a)
    {
        lastAxes = semiAxes;
        lastArea = 4*pi*sqr(a);
        return lastArea;
    }

    const scalar cosPhi = c/a;
    const scalar sinPhi = Foam::sqrt(1 - sqr(cosPhi));
    const scalar phi = std::acos(cosPhi);
    const scalar k =
        min(scalar(1), Foam::sqrt(sqr(a)*(sqr(b) - sqr(c))/(sqr(b)*(sqr(a) - sqr(c)))));

    const scalar E = std::tr1::ellint_2(k, phi);
    const scalar F = std::tr1::ellint_1(k, phi);

    lastAxes = semiAxes;
    lastArea =
        2*pi*sqr(c)
      + 2*pi*a*b/sinPhi*(E*sqr(sinPhi) + F*sqr(cosPhi));
    return lastArea;
}


Foam::ellipsoid Foam::ellipsoid::inflated(const scalar deltaBl) const
{
    if (!(deltaBl >= 0) || !std::isfinite(deltaBl))
    {
        FatalErrorInFunction
            << "Buffer-layer thickness delta_bl = " << deltaBl
            << " is invalid: it must be finite and >= 0 (Ruan Eq. 41)"
            << exit(FatalError);
    }
    return ellipsoid(semiAxes_ + vector::uniform(deltaBl), centre_, R_);
}


Foam::ellipsoid Foam::ellipsoid::moved
(
    const point& centre,
    const tensor& R
) const
{
    return ellipsoid(semiAxes_, centre, R);
}


Foam::vector Foam::ellipsoid::normal(const point& x) const
{
    const vector g = S_ & (x - centre_);
    const scalar m = mag(g);
    if (!(m > 0) || !std::isfinite(m))
    {
        FatalErrorInFunction
            << "No normal at " << x << ": it is the centre of the ellipsoid "
            << centre_ << " or not finite" << exit(FatalError);
    }
    return g/m;
}


Foam::scalar Foam::ellipsoid::curvature(const point& x) const
{
    const vector& ax = semiAxes_;
    const vector xb = ontoSurface(toBody(x), ax, "curvature");

    // Ruan Eq. (37) term by term, with u_i = x_i^2/a_i^2
    const scalar a2 = sqr(ax.x()), b2 = sqr(ax.y()), c2 = sqr(ax.z());
    const scalar ux = sqr(xb.x())/a2, uy = sqr(xb.y())/b2, uz = sqr(xb.z())/c2;

    // Eq. (37b)
    const scalar h = 1/Foam::sqrt(ux/a2 + uy/b2 + uz/c2);

    // Eq. (37a)
    return
        0.5*h*h*h
       *(
            (ux + uy)/(a2*b2)
          + (uy + uz)/(b2*c2)
          + (uz + ux)/(c2*a2)
        );
}


Foam::scalar Foam::ellipsoid::gaussianCurvature(const point& x) const
{
    const vector& ax = semiAxes_;
    const vector xb = ontoSurface(toBody(x), ax, "gaussianCurvature");
    const scalar a2 = sqr(ax.x()), b2 = sqr(ax.y()), c2 = sqr(ax.z());
    const scalar hm2 =
        sqr(xb.x())/sqr(a2) + sqr(xb.y())/sqr(b2) + sqr(xb.z())/sqr(c2);
    return 1/(a2*b2*c2*sqr(hm2));
}


Foam::point Foam::ellipsoid::support(const vector& m) const
{
    scalar h;
    return support(m, h);
}


Foam::point Foam::ellipsoid::support(const vector& m, scalar& h) const
{
    const vector w = Sinv_ & m;
    const scalar h2 = m & w;
    if (!(h2 > 0) || !std::isfinite(h2))
    {
        FatalErrorInFunction
            << "Support point for the direction " << m
            << " is undefined: the direction must be finite and non-zero"
            << exit(FatalError);
    }
    h = Foam::sqrt(h2);
    return centre_ + w/h;
}


Foam::SquareMatrix<Foam::scalar> Foam::ellipsoid::characteristicMatrix
(
    const scalar deltaBl
) const
{
    // Eq. (41) (Eq. 22 for deltaBl = 0) rotated and translated, Eq. (23):
    // P(x) = x^T S x - 2 (S x_c)^T x + x_c^T S x_c - 1 gives the blocks
    // S (Eq. 26), b/2 = -S x_c (Eq. 27), c = x_c^T S x_c - 1 (Eq. 28)
    const ellipsoid shell(inflated(deltaBl));  // checks deltaBl

    const tensor S(shell.S_);
    const vector Sc = shell.S_ & centre_;

    SquareMatrix<scalar> Q(4, Zero);
    for (direction i = 0; i < 3; ++i)
    {
        for (direction j = 0; j < 3; ++j)
        {
            Q(i, j) = S(i, j);
        }
        Q(i, 3) = -Sc[i];
        Q(3, i) = -Sc[i];
    }
    Q(3, 3) = (centre_ & Sc) - 1;

    return Q;
}


// * * * * * * * * * * * * * * * IOstream Operators  * * * * * * * * * * * * //

Foam::Ostream& Foam::operator<<(Ostream& os, const ellipsoid& e)
{
    os  << "ellipsoid(semiAxes " << e.semiAxes_
        << ", centre " << e.centre_
        << ", R " << e.R_ << ')';
    return os;
}


// ************************************************************************* //
