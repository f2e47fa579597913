// Tessellation (quadtri/far/tessellation.h): points shared along edges and at vertices, each
// face's inside a grid, joined to its edges by strips where the rates differ (docs/surface.md).
#include <quadtri/far/tessellation.h>

#include <algorithm>
#include <array>
#include <map>
#include <string>
#include <utility>

namespace quadtri {
inline namespace v0 {

namespace {

// Points along one side of a domain, both ends included, at parameters t from 0 to 1.
struct Chain {
    std::vector<int> points;
    std::vector<double> t;
    int segments() const { return int(points.size()) - 1; }
};

Chain reversed(const Chain& c) {
    Chain r;
    r.points.assign(c.points.rbegin(), c.points.rend());
    for (auto it = c.t.rbegin(); it != c.t.rend(); ++it) r.t.push_back(1.0 - *it);
    return r;
}

// Points at even steps, parameters k / (count - 1).
Chain evenChain(std::vector<int> points) {
    Chain c;
    const int n = int(points.size()) - 1;
    for (int k = 0; k <= n; ++k) c.t.push_back(n > 0 ? double(k) / n : 0.0);
    c.points = std::move(points);
    return c;
}

// Points [first, last] of `c` as a chain of their own.
Chain slice(const Chain& c, int first, int last) {
    std::vector<int> points(c.points.begin() + first, c.points.begin() + last + 1);
    return evenChain(std::move(points));
}

// Appends points and triangles for one face; a domain's (s, t) reaches the face's (u, v)
// through `toFace` (a quad sub-face's square, or the identity).
class FaceBuilder {
public:
    FaceBuilder(int face, std::vector<int>& faces, std::vector<double>& u, std::vector<double>& v,
                std::vector<int>& triangles, std::vector<int>& triangleFaces)
        : face_(face), faces_(faces), u_(u), v_(v), triangles_(triangles), triangleFaces_(triangleFaces) {}

    // The face's square (x, y) .. (x + scale, y + scale) for the domain that follows.
    void setDomain(double x, double y, double scale) {
        x_ = x;
        y_ = y;
        scale_ = scale;
    }

    int addPoint(double s, double t) {
        faces_.push_back(face_);
        u_.push_back(x_ + scale_ * s);
        v_.push_back(y_ + scale_ * t);
        return int(faces_.size()) - 1;
    }

    void triangle(int a, int b, int c) {
        triangles_.insert(triangles_.end(), {a, b, c});
        triangleFaces_.push_back(face_);
    }

    // The strip between `a` and `b`, both running the same way with the strip on their left:
    // each step advances the side whose next segment's middle comes first.
    void zip(const Chain& a, const Chain& b) {
        const int m = a.segments(), n = b.segments();
        int i = 0, j = 0;
        while (i < m || j < n) {
            const bool advanceA = j == n || (i < m && a.t[i] + a.t[i + 1] <= b.t[j] + b.t[j + 1]);
            if (advanceA) {
                triangle(a.points[i], a.points[i + 1], b.points[j]);
                ++i;
            } else {
                triangle(a.points[i], b.points[j + 1], b.points[j]);
                ++j;
            }
        }
    }

    // A quad domain from its four sides, counter-clockwise from corner 0 at (0, 0).
    void quad(const Chain (&side)[4]) {
        const int r0 = side[0].segments(), r1 = side[1].segments(), r2 = side[2].segments(), r3 = side[3].segments();
        if (r0 == r1 && r1 == r2 && r2 == r3) {
            const int n = r0;
            std::vector<int> g(std::size_t((n + 1) * (n + 1)));
            auto at = [&](int i, int j) -> int& { return g[std::size_t(j * (n + 1) + i)]; };
            for (int j = 0; j <= n; ++j)
                for (int i = 0; i <= n; ++i) {
                    if (j == 0)
                        at(i, j) = side[0].points[std::size_t(i)];
                    else if (i == n)
                        at(i, j) = side[1].points[std::size_t(j)];
                    else if (j == n)
                        at(i, j) = side[2].points[std::size_t(n - i)];
                    else if (i == 0)
                        at(i, j) = side[3].points[std::size_t(n - j)];
                    else
                        at(i, j) = addPoint(double(i) / n, double(j) / n);
                }
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    triangle(at(i, j), at(i + 1, j), at(i + 1, j + 1));
                    triangle(at(i, j), at(i + 1, j + 1), at(i, j + 1));
                }
            return;
        }
        const int nu = std::max(r0, r2), nv = std::max(r1, r3);
        if (nv == 1) return zip(side[0], reversed(side[2]));
        if (nu == 1) return zip(side[1], reversed(side[3]));
        // The inside: (nu - 1) x (nv - 1) points at (i / nu, j / nv), its rim one side per edge.
        std::vector<int> g(std::size_t((nu - 1) * (nv - 1)));
        auto at = [&](int i, int j) -> int& { return g[std::size_t((j - 1) * (nu - 1) + i - 1)]; };
        for (int j = 1; j < nv; ++j)
            for (int i = 1; i < nu; ++i) at(i, j) = addPoint(double(i) / nu, double(j) / nv);
        std::vector<int> rim[4];
        for (int i = 1; i < nu; ++i) rim[0].push_back(at(i, 1));
        for (int j = 1; j < nv; ++j) rim[1].push_back(at(nu - 1, j));
        for (int i = nu - 1; i >= 1; --i) rim[2].push_back(at(i, nv - 1));
        for (int j = nv - 1; j >= 1; --j) rim[3].push_back(at(1, j));
        for (int k = 0; k < 4; ++k) zip(side[k], evenChain(rim[k]));
        for (int j = 1; j + 1 < nv; ++j)
            for (int i = 1; i + 1 < nu; ++i) {
                triangle(at(i, j), at(i + 1, j), at(i + 1, j + 1));
                triangle(at(i, j), at(i + 1, j + 1), at(i, j + 1));
            }
    }

    // A triangle domain from its three sides, counter-clockwise from corner 0 at (0, 0).
    void triangleDomain(const Chain (&side)[3]) {
        const int r0 = side[0].segments(), r1 = side[1].segments(), r2 = side[2].segments();
        const bool uniform = r0 == r1 && r1 == r2;
        const int n = uniform ? r0 : std::max({3, r0, r1, r2});
        const int inset = uniform ? 0 : 1;  // the inside grid's first row and column
        std::vector<int> g(std::size_t((n + 1) * (n + 1)), -1);
        auto at = [&](int i, int j) -> int& { return g[std::size_t(j * (n + 1) + i)]; };
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i + j <= n; ++i) {
                if (uniform && j == 0)
                    at(i, j) = side[0].points[std::size_t(i)];
                else if (uniform && i + j == n)
                    at(i, j) = side[1].points[std::size_t(j)];
                else if (uniform && i == 0)
                    at(i, j) = side[2].points[std::size_t(n - j)];
                else if (i >= inset && j >= inset && i + j <= n - inset)
                    at(i, j) = addPoint(double(i) / n, double(j) / n);
            }
        if (!uniform) {
            std::vector<int> rim[3];
            for (int i = 1; i <= n - 2; ++i) rim[0].push_back(at(i, 1));
            for (int j = 1; j <= n - 2; ++j) rim[1].push_back(at(n - 1 - j, j));
            for (int j = n - 2; j >= 1; --j) rim[2].push_back(at(1, j));
            for (int k = 0; k < 3; ++k) zip(side[k], evenChain(rim[k]));
        }
        const int top = n - inset;  // i + j <= top inside
        for (int j = inset; j < top; ++j)
            for (int i = inset; i + j < top; ++i) {
                triangle(at(i, j), at(i + 1, j), at(i, j + 1));
                if (i + j + 1 < top) triangle(at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            }
    }

private:
    int face_;
    double x_ = 0, y_ = 0, scale_ = 1;
    std::vector<int>& faces_;
    std::vector<double>& u_;
    std::vector<double>& v_;
    std::vector<int>& triangles_;
    std::vector<int>& triangleFaces_;
};

void checkRate(int rate, const std::string& what) {
    if (rate < 1 || rate > Tessellation::kMaxRate)
        throw SurfaceError("Tessellation: " + what + " " + std::to_string(rate) + " is outside 1.." +
                           std::to_string(Tessellation::kMaxRate));
}

}  // namespace

Tessellation::Tessellation(const LimitSurface& surface, int rate) {
    checkRate(rate, "rate");
    build(surface, std::vector<int>(std::size_t(surface.topology().numEdges()), rate));
}

Tessellation::Tessellation(const LimitSurface& surface, const std::vector<int>& edgeRates) {
    const int numEdges = surface.topology().numEdges();
    if (int(edgeRates.size()) != numEdges)
        throw SurfaceError("Tessellation: " + std::to_string(edgeRates.size()) + " edge rates for " +
                           std::to_string(numEdges) + " edges");
    for (int e = 0; e < numEdges; ++e) checkRate(edgeRates[std::size_t(e)], "edge " + std::to_string(e) + "'s rate");
    build(surface, edgeRates);
}

void Tessellation::build(const LimitSurface& surface, std::vector<int> rates) {
    const Topology& t = surface.topology();
    using Type = FaceParameterization::Type;
    // Sub-faces meet at their face's edge midpoints: those edges take an even rate.
    for (int f = 0; f < t.numFaces(); ++f)
        if (!t.faceHole[std::size_t(f)] && surface.parameterization(f).type == Type::QuadSubFaces)
            for (int e : t.edgesOfFace(f)) rates[std::size_t(e)] += rates[std::size_t(e)] % 2;

    // An upper bound on the points, checked before anything is allocated.
    long long bound = t.numVertices;
    for (int f = 0; f < t.numFaces(); ++f) {
        if (t.faceHole[std::size_t(f)]) continue;
        long long most = 1;
        for (int e : t.edgesOfFace(f)) most = std::max<long long>(most, rates[std::size_t(e)]);
        bound += (most + 1) * (most + 1) * std::max(1, t.faceSize(f) - 2);
        if (bound > kMaxPoints)
            throw SurfaceError("Tessellation: these rates make more than " + std::to_string(kMaxPoints) +
                               " points (face " + std::to_string(f) + " reaches rate " + std::to_string(most) + ")");
    }

    edgeRates_ = std::move(rates);
    edgePoints_.assign(std::size_t(t.numEdges()), -1);
    vertexPoints_.assign(std::size_t(t.numVertices), -1);
    std::vector<Chain> sides;
    for (int f = 0; f < t.numFaces(); ++f) {
        if (t.faceHole[std::size_t(f)]) continue;
        const FaceParameterization p = surface.parameterization(f);
        const IndexSpan corners = t.verticesOfFace(f), edges = t.edgesOfFace(f);
        const int n = corners.size();
        // The face's first use of a vertex or an edge makes its points, at the face's (u, v).
        for (int k = 0; k < n; ++k) {
            int& point = vertexPoints_[std::size_t(corners[k])];
            if (point >= 0) continue;
            double u, v;
            p.cornerCoord(k, u, v);
            point = int(faces_.size());
            faces_.push_back(f);
            u_.push_back(u);
            v_.push_back(v);
        }
        sides.assign(std::size_t(n), Chain{});
        for (int k = 0; k < n; ++k) {
            const int e = edges[k], rate = edgeRates_[std::size_t(e)];
            const bool forward = t.edgeVerts[std::size_t(2 * e)] == corners[k];
            int& first = edgePoints_[std::size_t(e)];
            if (first < 0 && rate > 1) {
                first = int(faces_.size());
                for (int j = 1; j < rate; ++j) {
                    double u, v;
                    p.edgeCoord(k, forward ? double(j) / rate : 1.0 - double(j) / rate, u, v);
                    faces_.push_back(f);
                    u_.push_back(u);
                    v_.push_back(v);
                }
            }
            std::vector<int> points{vertexPoints_[std::size_t(corners[k])]};
            for (int j = 1; j < rate; ++j) points.push_back(first + (forward ? j - 1 : rate - 1 - j));
            points.push_back(vertexPoints_[std::size_t(corners[(k + 1) % n])]);
            sides[std::size_t(k)] = evenChain(std::move(points));
        }

        FaceBuilder b(f, faces_, u_, v_, triangles_, triangleFaces_);
        if (p.type == Type::Quad) {
            const Chain quad[4] = {sides[0], sides[1], sides[2], sides[3]};
            b.quad(quad);
            continue;
        }
        if (p.type == Type::Triangle) {
            const Chain tri[3] = {sides[0], sides[1], sides[2]};
            b.triangleDomain(tri);
            continue;
        }
        // Sub-face i: corner i, the middle of edge i, the centre, the middle of edge i - 1; a
        // spoke from each edge's middle to the centre, at half the edge's rate.
        double cu, cv;
        p.cornerCoord(0, cu, cv);
        b.setDomain(cu, cv, 0.5);
        const int centre = b.addPoint(1, 1);
        std::vector<Chain> spokes(sides.size());
        for (int k = 0; k < n; ++k) {
            const int half = sides[std::size_t(k)].segments() / 2;
            p.cornerCoord(k, cu, cv);
            b.setDomain(cu, cv, 0.5);
            std::vector<int> points{sides[std::size_t(k)].points[std::size_t(half)]};
            for (int j = 1; j < half; ++j) points.push_back(b.addPoint(1, double(j) / half));
            points.push_back(centre);
            spokes[std::size_t(k)] = evenChain(std::move(points));
        }
        for (int k = 0; k < n; ++k) {
            const int before = (k + n - 1) % n;
            const Chain& entering = sides[std::size_t(before)];
            const int half = sides[std::size_t(k)].segments() / 2, halfBefore = entering.segments() / 2;
            const Chain sub[4] = {slice(sides[std::size_t(k)], 0, half), spokes[std::size_t(k)],
                                  reversed(spokes[std::size_t(before)]),
                                  slice(entering, halfBefore, entering.segments())};
            p.cornerCoord(k, cu, cv);
            b.setDomain(cu, cv, 0.5);
            b.quad(sub);
        }
    }
}

// Each triangle corner's value is keyed by its point and the channel's values that place it: a
// vertex point by the face's value at the vertex, an edge point by the face's values at both
// ends of the edge (faces that agree there interpolate the same values along it), an inner
// point by itself.
Tessellation::FVarPoints Tessellation::fvarPoints(const LimitSurface& surface, int channel) const {
    const Topology& t = surface.topology();
    surface.numFVarValues(channel);  // the range check
    std::vector<int> vertexOf(std::size_t(numPoints()), -1), edgeOf(std::size_t(numPoints()), -1);
    for (int v = 0; v < t.numVertices; ++v)
        if (vertexPoints_[std::size_t(v)] >= 0) vertexOf[std::size_t(vertexPoints_[std::size_t(v)])] = v;
    for (int e = 0; e < t.numEdges(); ++e)
        for (int j = 0; j + 1 < edgeRates_[std::size_t(e)] && edgePoints_[std::size_t(e)] >= 0; ++j)
            edgeOf[std::size_t(edgePoints_[std::size_t(e)] + j)] = e;

    FVarPoints out;
    std::map<std::array<int, 3>, int> valueOfKey;  // points on base edges and vertices
    std::vector<int> innerValue(std::size_t(numPoints()), -1);
    for (std::size_t c = 0; c < triangles_.size(); ++c) {
        const int point = triangles_[c], face = triangleFaces_[c / 3];
        std::array<int, 3> key{point, -1, -1};
        double u = u_[std::size_t(point)], v = v_[std::size_t(point)];
        const FaceParameterization p = surface.parameterization(face);
        const IndexSpan corners = t.verticesOfFace(face), edges = t.edgesOfFace(face);
        const IndexSpan values = surface.fvarValuesOfFace(channel, face);
        const int n = corners.size();
        if (const int vertex = vertexOf[std::size_t(point)]; vertex >= 0) {
            int k = 0;
            while (corners[k] != vertex) ++k;
            key[1] = values[k];
            p.cornerCoord(k, u, v);
        } else if (const int edge = edgeOf[std::size_t(point)]; edge >= 0) {
            int k = 0;
            while (edges[k] != edge) ++k;
            const bool forward = t.edgeVerts[std::size_t(2 * edge)] == corners[k];
            key[1] = values[forward ? k : (k + 1) % n];
            key[2] = values[forward ? (k + 1) % n : k];
            const int rate = edgeRates_[std::size_t(edge)], j = point - edgePoints_[std::size_t(edge)] + 1;
            p.edgeCoord(k, forward ? double(j) / rate : 1.0 - double(j) / rate, u, v);
        }
        int& value = key[1] < 0 ? innerValue[std::size_t(point)] : valueOfKey.emplace(key, -1).first->second;
        if (value < 0) {
            value = out.numValues();
            out.faces.push_back(face);
            out.u.push_back(u);
            out.v.push_back(v);
        }
        out.cornerValues.push_back(value);
    }
    return out;
}

}  // namespace v0
}  // namespace quadtri
