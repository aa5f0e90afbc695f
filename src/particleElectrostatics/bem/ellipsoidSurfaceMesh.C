/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "ellipsoidSurfaceMesh.H"
#include "mathematicalConstants.H"
#include "error.H"
#include "unitConversion.H"

#include <algorithm>
#include <random>
#include <unordered_map>
#include <unordered_set>
#include <vector>

using Foam::constant::mathematical::pi;

// * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * * //

Foam::point Foam::ellipsoidSurfaceMesh::project
(
    const vector& s,
    const point& p
)
{
    // Closest point x_i = p_i a_i^2/(a_i^2 + lambda), g(lambda) = 0 with
    // g = sum (p_i a_i/(a_i^2 + lambda))^2 - 1 (convex, decreasing)
    const scalar amin2 = sqr(cmptMin(s));
    scalar lambda = 0;
    for (label it = 0; it < 60; ++it)
    {
        scalar g = -1, dg = 0;
        for (direction d = 0; d < 3; ++d)
        {
            const scalar a2 = sqr(s[d]);
            const scalar den = a2 + lambda;
            const scalar t = p[d]*s[d]/den;
            g += t*t;
            dg -= 2*t*t/den;
        }
        if (dg == 0)
        {
            break;
        }
        scalar lnew = lambda - g/dg;
        if (lnew <= -amin2)
        {
            lnew = 0.5*(lambda - amin2);
        }
        const bool done = mag(lnew - lambda) < 1e-15*(amin2 + mag(lambda));
        lambda = lnew;
        if (done)
        {
            break;
        }
    }
    point x;
    for (direction d = 0; d < 3; ++d)
    {
        x[d] = p[d]*sqr(s[d])/(sqr(s[d]) + lambda);
    }
    // Remove the last rounding off the surface radially
    scalar r = 0;
    for (direction d = 0; d < 3; ++d)
    {
        r += sqr(x[d]/s[d]);
    }
    return x/Foam::sqrt(r);
}


Foam::vector Foam::ellipsoidSurfaceMesh::normal
(
    const vector& s,
    const point& x
)
{
    const vector g(x.x()/sqr(s.x()), x.y()/sqr(s.y()), x.z()/sqr(s.z()));
    return g/mag(g);
}


Foam::scalar Foam::ellipsoidSurfaceMesh::meanCurvature
(
    const vector& s,
    const point& x
)
{
    // Level set F = sum x_i^2/a_i^2: H = (|g|^2 tr(Hs) - g.Hs.g)/(2|g|^3)
    const vector g(2*x.x()/sqr(s.x()), 2*x.y()/sqr(s.y()), 2*x.z()/sqr(s.z()));
    const vector h(2/sqr(s.x()), 2/sqr(s.y()), 2/sqr(s.z()));
    const scalar g2 = magSqr(g);
    const scalar gHg =
        sqr(g.x())*h.x() + sqr(g.y())*h.y() + sqr(g.z())*h.z();
    return (g2*(h.x() + h.y() + h.z()) - gHg)/(2*g2*Foam::sqrt(g2));
}


Foam::scalar Foam::ellipsoidSurfaceMesh::surfaceArea(const vector& s)
{
    // Midpoint rule in (t, phi), x = a cos t, y = b sin t cos phi, ...
    const label nt = 2000, np = 256;
    scalar A = 0;
    for (label i = 0; i < nt; ++i)
    {
        const scalar t = (i + 0.5)*pi/nt;
        for (label j = 0; j < np; ++j)
        {
            const scalar f = (j + 0.5)*2*pi/np;
            const vector rt
            (
                -s.x()*Foam::sin(t),
                s.y()*Foam::cos(t)*Foam::cos(f),
                s.z()*Foam::cos(t)*Foam::sin(f)
            );
            const vector rf
            (
                0,
               -s.y()*Foam::sin(t)*Foam::sin(f),
                s.z()*Foam::sin(t)*Foam::cos(f)
            );
            A += mag(rt ^ rf);
        }
    }
    return A*(pi/nt)*(2*pi/np);
}


Foam::scalar Foam::ellipsoidSurfaceMesh::inverseDistanceIntegral
(
    const point& a,
    const point& b,
    const point& c,
    const point& p
)
{
    // Sum over edges of the sub-triangle (p, v1, v2):
    // int dA/r = h [asinh(t2/h) - asinh(t1/h)], h = distance to the edge
    // line, t = position along the edge from the foot of the perpendicular
    const point v[3] = {a, b, c};
    scalar J = 0;
    for (label k = 0; k < 3; ++k)
    {
        const point& v1 = v[k];
        const point& v2 = v[(k + 1) % 3];
        const vector e = (v2 - v1)/mag(v2 - v1);
        const scalar t1 = (v1 - p) & e;
        const scalar t2 = (v2 - p) & e;
        const scalar h = mag((v1 - p) - t1*e);
        if (h > VSMALL)
        {
            J += h*(std::asinh(t2/h) - std::asinh(t1/h));
        }
    }
    return J;
}


namespace
{

// int dA/|x - y| over the curved triangle with surface vertices (x, b, c):
// the three children away from x by their centroid rule once they are
// small against their distance, the child at x recursively; the flat
// analytic integral at the last level
Foam::scalar curvedInverseDistance
(
    const Foam::vector& S,
    const Foam::point& x,
    const Foam::point& b,
    const Foam::point& c,
    const Foam::label depth
)
{
    using namespace Foam;
    if (depth == 0)
    {
        return ellipsoidSurfaceMesh::inverseDistanceIntegral(x, b, c, x);
    }
    const point xb = ellipsoidSurfaceMesh::project(S, 0.5*(x + b));
    const point bc = ellipsoidSurfaceMesh::project(S, 0.5*(b + c));
    const point cx = ellipsoidSurfaceMesh::project(S, 0.5*(c + x));
    // Regular children (b's corner, c's corner, the middle) by 4x4
    // subdivision centroids: their distance to x is at least half their size
    const point tri[3][3] = {{xb, b, bc}, {cx, bc, c}, {xb, bc, cx}};
    scalar J = 0;
    const label m = 4;
    for (const auto& t : tri)
    {
        auto node = [&](label i, label j)
        {
            const scalar u = scalar(i)/m, v = scalar(j)/m;
            return ellipsoidSurfaceMesh::project
            (
                S, t[0] + u*(t[1] - t[0]) + v*(t[2] - t[0])
            );
        };
        for (label i = 0; i < m; ++i)
        {
            for (label j = 0; j < m - i; ++j)
            {
                for (label up = 0; up < 2; ++up)
                {
                    if (up && i + j >= m - 1) continue;
                    const point p0 = up ? node(i + 1, j) : node(i, j);
                    const point p1 = node(i + 1, j + up);
                    const point p2 = node(i, j + 1);
                    const point y =
                        ellipsoidSurfaceMesh::project(S, (p0 + p1 + p2)/3);
                    J += 0.5*mag((p1 - p0) ^ (p2 - p0))/mag(x - y);
                }
            }
        }
    }
    return J + curvedInverseDistance(S, x, xb, cx, depth - 1);
}

// A face of the incremental convex hull: vertices (outward
// counter-clockwise), unit normal, offset n.x and whether still on the hull
struct hullFace
{
    Foam::label v[3];
    Foam::vector nrm;
    Foam::scalar off;
    bool alive;
};


hullFace makeHullFace
(
    const Foam::UList<Foam::point>& pts,
    const Foam::label a,
    const Foam::label b,
    const Foam::label c
)
{
    hullFace f;
    f.v[0] = a; f.v[1] = b; f.v[2] = c;
    Foam::vector nn = (pts[b] - pts[a]) ^ (pts[c] - pts[a]);
    f.nrm = nn/Foam::max(Foam::mag(nn), Foam::VSMALL);
    f.off = f.nrm & pts[a];
    f.alive = true;
    return f;
}


// The hull's initial tetrahedron from extreme points (its four vertices
// in i), its faces oriented outwards into F
void initialTetrahedron
(
    const Foam::UList<Foam::point>& pts,
    const Foam::scalar eps,
    std::vector<hullFace>& F,
    Foam::label i[4]
)
{
    using namespace Foam;
    const label n = pts.size();
    label i0 = 0, i1 = 0;
    for (label k = 1; k < n; ++k)
    {
        if (pts[k].x() < pts[i0].x()) i0 = k;
        if (pts[k].x() > pts[i1].x()) i1 = k;
    }
    const vector e01 = (pts[i1] - pts[i0])/mag(pts[i1] - pts[i0]);
    label i2 = -1;
    scalar best = -1;
    for (label k = 0; k < n; ++k)
    {
        const vector d = pts[k] - pts[i0];
        const scalar dl = mag(d - (d & e01)*e01);
        if (dl > best) { best = dl; i2 = k; }
    }
    vector n012 = (pts[i1] - pts[i0]) ^ (pts[i2] - pts[i0]);
    n012 /= mag(n012);
    label i3 = -1;
    best = -1;
    for (label k = 0; k < n; ++k)
    {
        const scalar dl = mag((pts[k] - pts[i0]) & n012);
        if (dl > best) { best = dl; i3 = k; }
    }
    if (best < eps)
    {
        FatalErrorInFunction << "Points are coplanar" << exit(FatalError);
    }
    const point cen = 0.25*(pts[i0] + pts[i1] + pts[i2] + pts[i3]);
    const label tet[4][3] = {{i0, i1, i2}, {i0, i1, i3}, {i0, i2, i3}, {i1, i2, i3}};
    for (label k = 0; k < 4; ++k)
    {
        hullFace f = makeHullFace(pts, tet[k][0], tet[k][1], tet[k][2]);
        if (((f.nrm & cen) - f.off) > 0)
        {
            f = makeHullFace(pts, tet[k][0], tet[k][2], tet[k][1]);
        }
        F.push_back(f);
    }
    i[0] = i0;
    i[1] = i1;
    i[2] = i2;
    i[3] = i3;
}


} // End anonymous namespace


Foam::scalarField Foam::ellipsoidSurfaceMesh::unitPotential() const
{
    const label nF = faces_.size();
    if (sphere())
    {
        return scalarField(nF, semiAxes_.x());
    }
    // Measured on graded spheres (1200 patches, lambda 0.3), against the
    // exact R: spread 1.3e-3 with the curved self patch, 3.9e-3 with the
    // flat selfJ
    scalarField u(nF, 0);
    for (label k = 0; k < nF; ++k)
    {
        const point& x = centres_[k];
        scalar J = 0;
        for (label j = 0; j < nF; ++j)
        {
            if (j == k)
            {
                for (label e = 0; e < 3; ++e)
                {
                    J += curvedInverseDistance
                    (
                        semiAxes_, x, points_[faces_[k][e]],
                        points_[faces_[k][(e + 1) % 3]], 4
                    );
                }
                continue;
            }
            for (label q = nQuad*j; q < nQuad*(j + 1); ++q)
            {
                J += quadWeights_[q]/mag(x - quadPoints_[q]);
            }
        }
        u[k] = J/(4*pi);
    }
    return u;
}


Foam::List<Foam::ellipsoidSurfaceMesh::triFace3>
Foam::ellipsoidSurfaceMesh::convexHull(const UList<point>& pts)
{
    const label n = pts.size();
    if (n < 4)
    {
        FatalErrorInFunction
            << "Need at least 4 points, got " << n << exit(FatalError);
    }

    std::vector<hullFace> F;
    F.reserve(4*n);

    scalar scale = 0;
    for (const point& p : pts)
    {
        scale = max(scale, mag(p));
    }
    const scalar eps = 1e-13*scale;
    auto makeFace = [&](label a, label b, label c)
    {
        return makeHullFace(pts, a, b, c);
    };

    label tet[4];
    initialTetrahedron(pts, eps, F, tet);
    const label i0 = tet[0], i1 = tet[1], i2 = tet[2], i3 = tet[3];

    // Deterministic shuffled insertion order (expected cost independent of
    // the generation order of the points)
    std::vector<label> order;
    for (label i = 0; i < n; ++i)
    {
        if (i != i0 && i != i1 && i != i2 && i != i3) order.push_back(i);
    }
    std::mt19937 rng(12345);
    std::shuffle(order.begin(), order.end(), rng);

    std::vector<label> visible;
    std::unordered_set<long long> edges;
    label nAlive = 4;
    label nSkipped = 0;

    for (const label p : order)
    {
        visible.clear();
        for (size_t k = 0; k < F.size(); ++k)
        {
            if (F[k].alive && ((F[k].nrm & pts[p]) - F[k].off) > eps)
            {
                visible.push_back(k);
            }
        }
        if (visible.empty())
        {
            ++nSkipped;
            continue;
        }
        edges.clear();
        for (const label k : visible)
        {
            for (label e = 0; e < 3; ++e)
            {
                edges.insert
                (
                    static_cast<long long>(F[k].v[e])*n + F[k].v[(e + 1) % 3]
                );
            }
        }
        for (const label k : visible)
        {
            F[k].alive = false;
            --nAlive;
            for (label e = 0; e < 3; ++e)
            {
                const label a = F[k].v[e], b = F[k].v[(e + 1) % 3];
                if (!edges.count(static_cast<long long>(b)*n + a))
                {
                    F.push_back(makeFace(a, b, p));
                    ++nAlive;
                }
            }
        }
        if (label(F.size()) > 3*nAlive + 64)
        {
            std::vector<hullFace> G;
            G.reserve(4*n);
            for (const hullFace& f : F) if (f.alive) G.push_back(f);
            F.swap(G);
        }
    }

    if (nSkipped)
    {
        FatalErrorInFunction
            << nSkipped << " of " << n << " points are not hull vertices:"
            << " the points are not on a strictly convex surface"
            << exit(FatalError);
    }

    List<triFace3> faces(nAlive);
    label m = 0;
    for (const hullFace& f : F)
    {
        if (f.alive)
        {
            faces[m++] = triFace3({f.v[0], f.v[1], f.v[2]});
        }
    }
    return faces;
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::scalar Foam::ellipsoidSurfaceMesh::sizeAt(const point& x) const
{
    // Relative patch size h ~ H^-beta (finer where the surface is curved)
    return beta_ == 0 ? 1 : std::pow(meanCurvature(semiAxes_, x), -beta_);
}


void Foam::ellipsoidSurfaceMesh::generatePoints(const label nV)
{
    // Longest axis L carries the poles; rings in the other two directions
    const vector& s = semiAxes_;
    direction L = 0;
    for (direction d = 1; d < 3; ++d) if (s[d] > s[L]) L = d;
    const direction i1 = (L + 1) % 3, i2 = (L + 2) % 3;
    const scalar a = s[L], b = s[i1], c = s[i2];
    const scalar re = 0.5*(b + c);
    // Ramanujan's perimeter of the ring ellipse (b, c)
    const scalar Pbc =
        pi*(3*(b + c) - Foam::sqrt((3*b + c)*(b + 3*c)));

    // Meridian table of the stretched length u(t) = int ds/h, t in [0, pi]
    // (h = 1: arc length)
    const label nt = 4000;
    std::vector<scalar> st(nt + 1, 0.0);
    auto meridianPoint = [&](scalar t)
    {
        point p(Zero);
        p[L] = a*Foam::cos(t);
        p[i1] = re*Foam::sin(t);
        return project(s, p);
    };
    auto hOfT = [&](scalar t) { return sizeAt(meridianPoint(t)); };
    for (label i = 1; i <= nt; ++i)
    {
        const scalar t = (i - 0.5)*pi/nt;
        st[i] = st[i - 1]
          + Foam::sqrt(sqr(a*Foam::sin(t)) + sqr(re*Foam::cos(t)))*pi/nt
           /hOfT(t);
    }
    const scalar S = st[nt];
    auto tOfS = [&](scalar sv)
    {
        const auto it = std::lower_bound(st.begin(), st.end(), sv);
        label i = min(max(label(it - st.begin()), label(1)), nt);
        const scalar f = (sv - st[i - 1])/max(st[i] - st[i - 1], VSMALL);
        return (i - 1 + f)*pi/nt;
    };

    std::vector<scalar> ringT;
    std::vector<label> ringM;
    auto layout = [&](scalar h)
    {
        const label nR =
            max(label(1), label(std::round(S/(h*Foam::sqrt(3.0)/2))) - 1);
        ringT.resize(nR);
        ringM.resize(nR);
        label cnt = 2;
        for (label k = 0; k < nR; ++k)
        {
            ringT[k] = tOfS((k + 1)*S/(nR + 1));
            ringM[k] = max
            (
                label(3),
                label
                (
                    std::round(Foam::sin(ringT[k])*Pbc/(h*hOfT(ringT[k])))
                )
            );
            cnt += ringM[k];
        }
        return cnt;
    };

    const scalar Aapprox = surfaceArea(s);
    scalar h = Foam::sqrt(2*Aapprox/(Foam::sqrt(3.0)*nV))/hOfT(0.5*pi);
    for (label it = 0; it < 20; ++it)
    {
        const label cnt = layout(h);
        if (cnt == nV) break;
        h *= Foam::sqrt(scalar(cnt)/nV);
    }
    label cnt = layout(h);
    // Fix the remaining difference one point at a time on the rings whose
    // spacing is furthest from h
    while (cnt != nV)
    {
        label best = -1;
        scalar bestVal = 0;
        for (size_t k = 0; k < ringM.size(); ++k)
        {
            const scalar spacing =
                Foam::sin(ringT[k])*Pbc/ringM[k]/hOfT(ringT[k]);
            const scalar val = (cnt < nV) ? spacing : -spacing;
            if (cnt > nV && ringM[k] <= 3) continue;
            if (best < 0 || val > bestVal) { best = k; bestVal = val; }
        }
        if (best < 0)
        {
            FatalErrorInFunction << "Cannot lay out " << nV << " vertices"
                << exit(FatalError);
        }
        ringM[best] += (cnt < nV) ? 1 : -1;
        cnt += (cnt < nV) ? 1 : -1;
    }

    points_.setSize(nV);
    std::mt19937 rng(4321);
    std::uniform_real_distribution<scalar> U(-1, 1);
    label m = 0;
    point p0(Zero);
    p0[L] = a;
    points_[m++] = p0;
    p0[L] = -a;
    points_[m++] = p0;
    for (size_t k = 0; k < ringM.size(); ++k)
    {
        const scalar t = ringT[k];
        for (label j = 0; j < ringM[k]; ++j)
        {
            // Half-step shift on alternate rings, small jitter against
            // exactly cocircular quadruples
            const scalar f =
                2*pi*(j + 0.5*(k % 2) + 1e-3*U(rng))/ringM[k];
            point p;
            p[L] = a*Foam::cos(t);
            p[i1] = b*Foam::sin(t)*Foam::cos(f);
            p[i2] = c*Foam::sin(t)*Foam::sin(f);
            points_[m++] = project(s, p);
        }
    }
}


Foam::label Foam::ellipsoidSurfaceMesh::flipEdges()
{
    // Lawson edge flips to the Delaunay criterion measured on the real
    // surface: the convex hull is Delaunay only in the frame scaled to the
    // unit sphere, which for elongated shapes prefers long edges along the
    // major axis
    const label nV = points_.size();
    auto key = [nV](label a, label b)
    {
        return static_cast<long long>(a)*nV + b;
    };
    std::unordered_map<long long, label> edgeFace;
    edgeFace.reserve(3*faces_.size());
    forAll(faces_, fi)
    {
        for (label e = 0; e < 3; ++e)
        {
            edgeFace[key(faces_[fi][e], faces_[fi][(e + 1) % 3])] = fi;
        }
    }
    auto third = [](const triFace3& f, label u, label v)
    {
        for (label k = 0; k < 3; ++k)
        {
            if (f[k] != u && f[k] != v) return f[k];
        }
        return label(-1);
    };
    auto angle = [&](label apex, label u, label v)
    {
        const vector a = points_[u] - points_[apex];
        const vector b = points_[v] - points_[apex];
        return Foam::acos(max(-1.0, min(1.0, (a & b)/(mag(a)*mag(b)))));
    };

    label nFlips = 0;
    for (label pass = 0; pass < 100; ++pass)
    {
        label flipped = 0;
        forAll(faces_, fi)
        {
            for (label e = 0; e < 3; ++e)
            {
                const label u = faces_[fi][e];
                const label v = faces_[fi][(e + 1) % 3];
                if (u > v) continue;
                const label gi = edgeFace[key(v, u)];
                const label p = third(faces_[fi], u, v);
                const label q = third(faces_[gi], u, v);
                if (angle(p, u, v) + angle(q, u, v) <= pi + 1e-10) continue;
                if (edgeFace.count(key(p, q)) || edgeFace.count(key(q, p)))
                {
                    continue;
                }
                // (u,v,p) + (v,u,q) -> (u,q,p) + (q,v,p)
                faces_[fi] = triFace3({u, q, p});
                faces_[gi] = triFace3({q, v, p});
                edgeFace.erase(key(u, v));
                edgeFace.erase(key(v, u));
                edgeFace[key(u, q)] = fi;
                edgeFace[key(q, p)] = fi;
                edgeFace[key(p, u)] = fi;
                edgeFace[key(q, v)] = gi;
                edgeFace[key(v, p)] = gi;
                edgeFace[key(p, q)] = gi;
                ++flipped;
                break;   // face fi changed: its other edges next pass
            }
        }
        nFlips += flipped;
        if (!flipped) break;
    }
    return nFlips;
}


void Foam::ellipsoidSurfaceMesh::relax(const label nIter)
{
    // DistMesh (Persson & Strang 2004) on a closed surface: bars longer
    // than L0 = 1.2 x rms length feel no force, shorter ones push apart;
    // projection back to the surface provides the closing constraint.
    // Connectivity: hull once, then edge flips every step.
    const label nV = points_.size();
    std::vector<std::pair<label, label>> bars;
    std::vector<scalar> hBar;
    vectorField force(nV);
    const scalar dt = 0.2;

    faces_ = convexHull(points_);
    for (label it = 0; it < nIter; ++it)
    {
        flipEdges();
        bars.clear();
        forAll(faces_, fi)
        {
            const triFace3& f = faces_[fi];
            for (label e = 0; e < 3; ++e)
            {
                const label a = f[e], b = f[(e + 1) % 3];
                if (a < b) bars.push_back({a, b});
            }
        }
        scalar sumL2 = 0, sumH2 = 0;
        hBar.resize(bars.size());
        for (size_t b = 0; b < bars.size(); ++b)
        {
            const auto& e = bars[b];
            sumL2 += magSqr(points_[e.first] - points_[e.second]);
            hBar[b] =
                beta_ == 0 ? 1
              : sizeAt
                (
                    project
                    (
                        semiAxes_,
                        0.5*(points_[e.first] + points_[e.second])
                    )
                );
            sumH2 += sqr(hBar[b]);
        }
        const scalar L0 = 1.2*Foam::sqrt(sumL2/sumH2);
        force = Zero;
        for (size_t b = 0; b < bars.size(); ++b)
        {
            const auto& e = bars[b];
            const vector d = points_[e.first] - points_[e.second];
            const scalar Lb = mag(d);
            const scalar Fb = max(L0*hBar[b] - Lb, scalar(0));
            const vector fv = Fb*d/max(Lb, VSMALL);
            force[e.first] += fv;
            force[e.second] -= fv;
        }
        for (label i = 0; i < nV; ++i)
        {
            points_[i] = project(semiAxes_, points_[i] + dt*force[i]);
        }
    }
    flipEdges();
}


void Foam::ellipsoidSurfaceMesh::grade()
{
    if (lambda_ == 1)
    {
        return;
    }
    const vector& s = semiAxes_;
    // Focus direction on the scaled unit sphere
    vector f(focus_.x()/s.x(), focus_.y()/s.y(), focus_.z()/s.z());
    f /= mag(f);
    for (point& p : points_)
    {
        vector u(p.x()/s.x(), p.y()/s.y(), p.z()/s.z());
        u /= mag(u);
        const scalar ct = max(-1.0, min(1.0, u & f));
        const scalar t = Foam::acos(ct);
        vector e = u - ct*f;
        const scalar me = mag(e);
        if (me < 1e-14)
        {
            continue;   // on the axis: fixed point of the map
        }
        e /= me;
        const scalar t2 = 2*Foam::atan(lambda_*Foam::tan(0.5*t));
        const vector u2 = Foam::cos(t2)*f + Foam::sin(t2)*e;
        p = project(s, point(u2.x()*s.x(), u2.y()*s.y(), u2.z()*s.z()));
    }
    flipEdges();
}


void Foam::ellipsoidSurfaceMesh::computePatchData()
{
    const label nF = faces_.size();
    centres_.setSize(nF);
    chargeShifts_.setSize(nF);
    normals_.setSize(nF);
    areas_.setSize(nF);
    meanCurvature_.setSize(nF);
    selfJ_.setSize(nF);
    quadPoints_.setSize(nQuad*nF);
    quadWeights_.setSize(nQuad*nF);

    const label m = 4;   // subdivisions per edge: m^2 = nQuad sub-triangles

    for (label fi = 0; fi < nF; ++fi)
    {
        const point& A = points_[faces_[fi][0]];
        const point& B = points_[faces_[fi][1]];
        const point& C = points_[faces_[fi][2]];
        const point cf = (A + B + C)/3;

        centres_[fi] = project(semiAxes_, cf);
        normals_[fi] = normal(semiAxes_, centres_[fi]);
        meanCurvature_[fi] = meanCurvature(semiAxes_, centres_[fi]);
        selfJ_[fi] = inverseDistanceIntegral(A, B, C, cf);

        auto node = [&](label i, label j)
        {
            const scalar u = scalar(i)/m, v = scalar(j)/m;
            return project(semiAxes_, A + u*(B - A) + v*(C - A));
        };
        scalar area = 0;
        label q = nQuad*fi;
        for (label i = 0; i < m; ++i)
        {
            for (label j = 0; j < m - i; ++j)
            {
                // Upward sub-triangle
                {
                    const point p0 = node(i, j), p1 = node(i + 1, j),
                        p2 = node(i, j + 1);
                    const scalar w = 0.5*mag((p1 - p0) ^ (p2 - p0));
                    quadPoints_[q] = project(semiAxes_, (p0 + p1 + p2)/3);
                    quadWeights_[q++] = w;
                    area += w;
                }
                if (i + j < m - 1)
                {
                    const point p0 = node(i + 1, j), p1 = node(i + 1, j + 1),
                        p2 = node(i, j + 1);
                    const scalar w = 0.5*mag((p1 - p0) ^ (p2 - p0));
                    quadPoints_[q] = project(semiAxes_, (p0 + p1 + p2)/3);
                    quadWeights_[q++] = w;
                    area += w;
                }
            }
        }
        areas_[fi] = area;
        point c = Zero;
        for (label l = nQuad*fi; l < nQuad*(fi + 1); ++l)
        {
            c += quadWeights_[l]*quadPoints_[l];
        }
        chargeShifts_[fi] = c/area - centres_[fi];
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::ellipsoidSurfaceMesh::ellipsoidSurfaceMesh
(
    const vector& semiAxes,
    const label nPatches,
    const vector& focus,
    const scalar lambda,
    const label nRelax,
    const scalar beta
)
:
    semiAxes_(semiAxes),
    focus_(focus/max(mag(focus), VSMALL)),
    lambda_(lambda),
    beta_(beta)
{
    if (!(lambda > 0 && lambda <= 1) || mag(focus) < VSMALL)
    {
        FatalErrorInFunction
            << "grading lambda = " << lambda << " out of range (0, 1] or"
            << " zero focus direction " << focus << exit(FatalError);
    }
    const label nF = nPatches + (nPatches % 2);
    generatePoints(nF/2 + 2);
    relax(nRelax);
    grade();
    computePatchData();
}


Foam::ellipsoidSurfaceMesh::ellipsoidSurfaceMesh
(
    const vector& semiAxes,
    const label nPatches,
    const label nRelax,
    const scalar beta
)
:
    semiAxes_(semiAxes),
    focus_(1, 0, 0),
    lambda_(1),
    beta_(beta)
{
    if (cmptMin(semiAxes) <= 0 || !std::isfinite(cmptMax(semiAxes)))
    {
        FatalErrorInFunction
            << "semiAxes " << semiAxes << " out of range: all must be > 0"
            << exit(FatalError);
    }
    if (!(beta >= 0 && beta <= 1))
    {
        FatalErrorInFunction
            << "curvature grading exponent beta = " << beta
            << " out of range [0, 1]" << exit(FatalError);
    }
    if (nPatches < 8 || nPatches > 200000)
    {
        FatalErrorInFunction
            << "nPatches = " << nPatches << " out of range [8, 200000]"
            << exit(FatalError);
    }
    const label nF = nPatches + (nPatches % 2);
    generatePoints(nF/2 + 2);
    relax(nRelax);
    computePatchData();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::ellipsoidSurfaceMesh::qualityStats
Foam::ellipsoidSurfaceMesh::quality() const
{
    qualityStats q;
    q.areaMin = min(areas_);
    q.areaMax = max(areas_);
    q.totalArea = sum(areas_);
    q.areaMean = q.totalArea/areas_.size();
    q.areaStd = Foam::sqrt(sum(sqr(areas_ - q.areaMean))/areas_.size());
    q.angleMin = 180;
    q.angleMax = 0;
    for (const triFace3& f : faces_)
    {
        for (label k = 0; k < 3; ++k)
        {
            const vector u = points_[f[(k + 1) % 3]] - points_[f[k]];
            const vector v = points_[f[(k + 2) % 3]] - points_[f[k]];
            const scalar ang = radToDeg
            (
                Foam::acos(max(-1.0, min(1.0, (u & v)/(mag(u)*mag(v)))))
            );
            q.angleMin = min(q.angleMin, ang);
            q.angleMax = max(q.angleMax, ang);
        }
    }
    q.exactArea = surfaceArea(semiAxes_);
    return q;
}


void Foam::ellipsoidSurfaceMesh::writeQuality(Ostream& os) const
{
    const qualityStats q = quality();
    os  << "ellipsoid " << semiAxes_ << ": " << size() << " patches, "
        << points_.size() << " vertices" << nl
        << "    area min/mean/max " << q.areaMin << " / " << q.areaMean
        << " / " << q.areaMax << ", std/mean " << q.areaStd/q.areaMean
        << ", max/min " << q.areaMax/q.areaMin << nl
        << "    angles [deg] " << q.angleMin << " .. " << q.angleMax << nl
        << "    total area " << q.totalArea << " (quadrature "
        << q.exactArea << ", rel. diff "
        << (q.totalArea - q.exactArea)/q.exactArea << ")" << endl;
}


// ************************************************************************* //
