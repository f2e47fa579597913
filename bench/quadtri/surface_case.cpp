#include "bench/quadtri/surface_case.h"

#include <random>

#include "bench/compare.h"
#include <quadtri/far/limit_surface.h>

namespace quadtri::bench {

TopologyDescriptor SurfaceCage::descriptor() const {
    TopologyDescriptor desc = mesh.descriptor();
    desc.numCreases = int(creaseSharpness.size());
    desc.creaseVertexPairs = creasePairs.data();
    desc.creaseWeights = creaseSharpness.data();
    desc.numCorners = int(cornerSharpness.size());
    desc.cornerVertexIndices = corners.data();
    desc.cornerWeights = cornerSharpness.data();
    desc.numHoles = int(holes.size());
    desc.holeIndices = holes.data();
    return desc;
}

namespace {

// A point of the face's domain, uniform over it (a sub-face's square where the face has them).
std::pair<double, double> randomPoint(const FaceParameterization& p, std::mt19937& random) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    double u = unit(random), v = unit(random);
    if (p.type == FaceParameterization::Type::Triangle && u + v > 1) {
        u = 1 - u;
        v = 1 - v;
    } else if (p.type == FaceParameterization::Type::QuadSubFaces) {
        const int i = int(unit(random) * p.faceSize) % p.faceSize;
        u = i % p.gridWidth + 0.5 * u;
        v = i / p.gridWidth + 0.5 * v;
    }
    return {u, v};
}

}  // namespace

SurfaceCase::SurfaceCase(const SurfaceCage& cage, int pointsPerFace) : cage_(cage), pointsPerFace_(pointsPerFace) {}
SurfaceCase::~SurfaceCase() = default;

void SurfaceCase::prepare() {
    surface_ = std::make_unique<LimitSurface>(cage_.descriptor(), cage_.options);
    std::mt19937 random(2026);
    for (int f = 0; f < surface_->numFaces(); ++f) {
        if (surface_->isHole(f)) continue;
        const FaceParameterization p = surface_->parameterization(f);
        for (int k = 0; k < pointsPerFace_; ++k) {
            const auto [u, v] = randomPoint(p, random);
            points_.faces.push_back(f);
            points_.u.push_back(u);
            points_.v.push_back(v);
        }
    }
    position_.assign(3 * std::size_t(points_.size()), 0.0f);
    normal_ = du_ = dv_ = position_;
    warm_ = std::make_unique<FaceSurfaceFactory>(*surface_);
    evaluate(*warm_);
}

void SurfaceCase::evaluate(FaceSurfaceFactory& factory) {
    const float* control = cage_.mesh.positions.data();
    FaceSurface surface;
    for (int first = 0, end = 0; first < points_.size(); first = end) {
        while (end < points_.size() && points_.faces[std::size_t(end)] == points_.faces[std::size_t(first)]) ++end;
        factory.faceSurface(points_.faces[std::size_t(first)], surface);
        const std::size_t at = 3 * std::size_t(first);
        surface.evaluate(end - first, &points_.u[std::size_t(first)], &points_.v[std::size_t(first)], control, 3, 3,
                         &position_[at], &du_[at], &dv_[at]);
        for (std::size_t i = at; i < 3 * std::size_t(end); i += 3) unitNormal(&du_[i], &dv_[i], &normal_[i]);
    }
}

SurfaceWay SurfaceCase::measure(int reps) {
    SurfaceWay way;
    way.library = "quadtri";
    way.way = "face_surface";
    const TopologyDescriptor descriptor = cage_.descriptor();
    way.factoryMs = timeMs(reps, [&] {
        const LimitSurface surface(descriptor, cage_.options);
        FaceSurfaceFactory factory(surface);
    });
    way.pointsMs = timeMs(reps, [&] {
        FaceSurfaceFactory factory(*surface_);
        evaluate(factory);
    });
    way.warmMs = timeMs(reps, [&] { evaluate(*warm_); });
    return way;
}

}  // namespace quadtri::bench
