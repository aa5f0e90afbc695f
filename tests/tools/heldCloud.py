#!/usr/bin/env python3
"""cloudProperties of parcels held in place (rho0 1e30) for one-step static
checks of the electrostatics: no collisions, a particle history every step.

    heldCloud.cloudProperties(electrostatics, parcels) -> text

electrostatics: the subModels entries of the electrostatics model (model,
coefficients, applied field); parcels: explicitParcels entries, one a line.
"""

TEMPLATE = """FoamFile {{ version 2.0; format ascii; class dictionary; object cloudProperties; }}
solution
{{
    active true; coupled false; transient yes; cellValueSourceCorrection off; maxCo 0.3;
    interpolationSchemes {{ rho.carrier cell; U.carrier cell; mu.carrier cell; }}
    integrationSchemes {{ U Euler; }}
    sourceTerms {{ schemes {{}} }}
}}
constantProperties {{ rho0 1e30; }}     // parcels held in place
subModels
{{
    particleForces {{}}
{electrostatics}
    injectionModels
    {{
        parcels
        {{
            type explicitParcels; SOI 0;
            parcels
            (
{parcels}
            );
        }}
    }}
    collisionModel none; dispersionModel none;
    patchInteractionModel standardWallInteraction;
    standardWallInteractionCoeffs {{ type rebound; e 1; mu 0; }}
    stochasticCollisionModel none; surfaceFilmModel none;
}}
cloudFunctions {{ particleHistory {{ type particleHistory; interval 1; }} }}
"""


def cloudProperties(electrostatics, parcels):
    return TEMPLATE.format(electrostatics=electrostatics, parcels=parcels)
