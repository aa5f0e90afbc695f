/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "hertzOnset.H"
#include "error.H"

#include <cmath>

// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * * //

Foam::hertzOnset::zetaPair Foam::hertzOnset::hertzZeta(const scalar q)
{
    if (!(q > 0 && q <= 1))
    {
        FatalErrorInFunction
            << "hertzZeta(q = " << q << "): q must be in (0, 1]"
            << exit(FatalError);
    }

    // Euler-Maclaurin with s = -p: sum_{k<N} (q + k)^p + x^(p+1)/(-p-1)
    //   + x^p/2 + sum_j B_2j/(2j)! s (s+1) ... (s+2j-2) x^(p-2j+1),
    // x = q + N
    constexpr int N = 8;
    zetaPair z{0, 0};
    for (int k = 0; k < N; ++k)
    {
        const scalar t = q + k;
        const scalar t32 = t*std::sqrt(t);
        z.s32 += t32;
        z.s52 += t*t32;
    }

    const scalar x = q + N;
    const scalar sqrtX = std::sqrt(x);
    const scalar x12 = sqrtX, x32 = x*sqrtX, x52 = x*x32, x72 = x*x52;
    z.s32 += -x52/2.5 + 0.5*x32;
    z.s52 += -x72/3.5 + 0.5*x52;

    // B_2j/(2j)! for j = 1..5
    constexpr scalar bernoulliByFactorial[5] =
    {
        1.0/6/2,
        -1.0/30/24,
        1.0/42/720,
        -1.0/30/40320,
        5.0/66/3628800
    };
    const scalar invX2 = 1/(x*x);
    scalar rising32 = -1.5, rising52 = -2.5;    // s (s+1) ... (s+2j-2)
    scalar pow32 = x12, pow52 = x32;            // x^(p-2j+1)
    for (int j = 1; j <= 5; ++j)
    {
        if (j > 1)
        {
            rising32 *= (-1.5 + 2*j - 3)*(-1.5 + 2*j - 2);
            rising52 *= (-2.5 + 2*j - 3)*(-2.5 + 2*j - 2);
            pow32 *= invX2;
            pow52 *= invX2;
        }
        z.s32 += bernoulliByFactorial[j - 1]*rising32*pow32;
        z.s52 += bernoulliByFactorial[j - 1]*rising52*pow52;
    }
    return z;
}


Foam::hertzOnset::correction Foam::hertzOnset::onsetCorrection
(
    const scalar delta,
    const scalar w
)
{
    // phi = delta/w in (0, 1]; above 1 (a prediction off by round-off) the
    // step is not the first (last) in contact
    if (!(w > 0) || !(delta > 0) || !(delta <= w))
    {
        return {0, 0};
    }
    const zetaPair z = hertzZeta(delta/w);
    const scalar w32 = w*std::sqrt(w);
    return {w32*z.s32, w*w32*z.s52};
}


// ************************************************************************* //
