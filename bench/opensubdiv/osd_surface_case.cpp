#include "bench/opensubdiv/osd_surface_case.h"

#include <opensubdiv/bfr/parameterization.h>
#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>
#include <opensubdiv/far/patchMap.h>
#include <opensubdiv/far/patchTableFactory.h>
#include <opensubdiv/far/ptexIndices.h>
#include <opensubdiv/far/stencilTableFactory.h>
#include <opensubdiv/osd/cpuEvaluator.h>
#include <opensubdiv/osd/cpuPatchTable.h>

#include <cmath>
#include <stdexcept>
#include <type_traits>

#include "bench/compare.h"
#include "bench/opensubdiv/osd_topology.h"

namespace quadtri::bench {

namespace Bfr = OpenSubdiv::Bfr;
namespace Far = OpenSubdiv::Far;
namespace Osd = OpenSubdiv::Osd;
namespace Sdc = OpenSubdiv::Sdc;

namespace {

constexpr int kPatchIsolation = 2;

// Where one way puts its points.
struct Output {
    std::vector<float> position, normal;
};

// The Far::PatchTable route: the refiner refined adaptively, its patch table, every vertex the
// patches read (refined levels and local points) as one stencil table over the control vertices.
struct PatchRoute {
    std::unique_ptr<Far::TopologyRefiner> refiner;
    std::unique_ptr<Far::PatchTable> table;
    std::unique_ptr<Far::PatchMap> map;
    std::unique_ptr<Osd::CpuPatchTable> cpuTable;
    std::unique_ptr<const Far::StencilTableReal<float>> stencils;
    std::vector<int> ptexOfFace;  // the face's first ptex face
};

}  // namespace

struct OsdSurfaceCase::State {
    const SurfaceCage& cage;
    OsdScheme scheme;
    const SurfacePoints& points;
    std::unique_ptr<Far::TopologyRefiner> refiner;  // unrefined: Bfr's
    PatchRoute patches;
    std::vector<float> vertices;           // the patch route's control, refined and local points
    std::vector<Osd::PatchCoord> coords;   // per point, found once by prepare() for the warm runs
    std::vector<float> du, dv;
    Output bfrDefault, bfr10, patch;
    Output reference;  // Bfr at level 10 in double: in float its deep patches lose digits

    State(const SurfaceCage& c, OsdScheme s, const SurfacePoints& p) : cage(c), scheme(s), points(p) {}

    std::unique_ptr<Far::TopologyRefiner> newRefiner() const {
        return osdTopologyRefiner(cage.mesh, scheme, cage.creasePairs, cage.creaseSharpness);
    }
    Sdc::SchemeType sdcScheme() const { return scheme == OsdScheme::Catmark ? Sdc::SCHEME_CATMARK : Sdc::SCHEME_LOOP; }

    static Bfr::RefinerSurfaceFactory<>::Options bfrOptions(int approxLevel) {
        Bfr::RefinerSurfaceFactory<>::Options options;
        if (approxLevel > 0) options.SetApproxLevelSmooth(approxLevel).SetApproxLevelSharp(approxLevel);
        return options;  // else Bfr's defaults
    }

    // Every point by Bfr::Surface<Real> from `factory`, grouped by face as the points are.
    template <class Real = float>
    void evalBfr(const Bfr::RefinerSurfaceFactory<>& factory, Output& out) {
        const typename Bfr::Surface<Real>::PointDescriptor layout(3);
        std::vector<Real> converted;
        const Real* controlPoints = nullptr;
        if constexpr (std::is_same<Real, float>::value) {
            controlPoints = cage.mesh.positions.data();
        } else {
            converted.assign(cage.mesh.positions.begin(), cage.mesh.positions.end());
            controlPoints = converted.data();
        }
        Bfr::Surface<Real> surface;
        std::vector<Real> patchPoints;
        for (int i = 0; i < points.size(); ++i) {
            if (i == 0 || points.faces[i] != points.faces[i - 1]) {
                if (!factory.InitVertexSurface(points.faces[i], &surface))
                    throw std::runtime_error(cage.mesh.name + ": Bfr has no surface for face " +
                                             std::to_string(points.faces[i]));
                patchPoints.resize(3 * std::size_t(surface.GetNumPatchPoints()));
                surface.PreparePatchPoints(controlPoints, layout, patchPoints.data(), layout);
            }
            const Real uv[2] = {Real(points.u[std::size_t(i)]), Real(points.v[std::size_t(i)])};
            Real p[3], d[6];
            surface.Evaluate(uv, patchPoints.data(), layout, p, d, d + 3);
            float du[3], dv[3];
            for (int c = 0; c < 3; ++c) {
                out.position[3 * std::size_t(i) + std::size_t(c)] = float(p[c]);
                du[c] = float(d[c]);
                dv[c] = float(d[3 + c]);
            }
            unitNormal(du, dv, &out.normal[3 * std::size_t(i)]);
        }
    }

    void buildPatches(PatchRoute& r) const {
        r.refiner = newRefiner();
        r.refiner->RefineAdaptive(Far::TopologyRefiner::AdaptiveOptions(kPatchIsolation));
        Far::PatchTableFactory::Options options(kPatchIsolation);
        options.SetEndCapType(Far::PatchTableFactory::Options::ENDCAP_GREGORY_BASIS);
        r.table.reset(Far::PatchTableFactory::Create(*r.refiner, options));
        // The templates, not Far::StencilTableFactory's wrappers: those static_cast what they build to
        // the subclass StencilTable, a downcast UBSan rejects (as bench/opensubdiv/osd_case.cpp says).
        using Factory = Far::StencilTableFactoryReal<float>;
        Factory::Options stencilOptions;
        stencilOptions.generateOffsets = true;
        stencilOptions.generateIntermediateLevels = true;
        std::unique_ptr<const Far::StencilTableReal<float>> refined(Factory::Create(*r.refiner, stencilOptions));
        if (const Far::StencilTableReal<float>* local = r.table->GetLocalPointStencilTable<float>())
            r.stencils.reset(Factory::AppendLocalPointStencilTable(*r.refiner, refined.get(), local));
        else
            r.stencils = std::move(refined);
        r.map = std::make_unique<Far::PatchMap>(*r.table);
        r.cpuTable.reset(Osd::CpuPatchTable::Create(r.table.get()));
        const Far::PtexIndices ptex(*r.refiner);
        r.ptexOfFace.resize(std::size_t(r.refiner->GetLevel(0).GetNumFaces()));
        for (std::size_t f = 0; f < r.ptexOfFace.size(); ++f) r.ptexOfFace[f] = ptex.GetFaceId(int(f));
    }

    // The control points, then every refined and local point from them.
    void patchVertices() {
        const int numControl = cage.mesh.numVertices;
        vertices.resize(3 * std::size_t(numControl + patches.stencils->GetNumStencils()));
        std::copy(cage.mesh.positions.begin(), cage.mesh.positions.end(), vertices.begin());
        const Far::StencilTableReal<float>& t = *patches.stencils;
        if (t.GetNumStencils() == 0) return;
        Osd::CpuEvaluator::EvalStencils(vertices.data(), Osd::BufferDescriptor(0, 3, 3),
                                        vertices.data() + 3 * std::size_t(numControl), Osd::BufferDescriptor(0, 3, 3),
                                        t.GetSizes().data(), t.GetOffsets().data(), t.GetControlIndices().data(),
                                        t.GetWeights().data(), 0, t.GetNumStencils());
    }

    // Each point's patch and its (s, t) there: a face with sub-faces has one ptex face each.
    void findPatches() {
        coords.resize(std::size_t(points.size()));
        for (int i = 0; i < points.size(); ++i) {
            const int f = points.faces[i];
            const Bfr::Parameterization param(sdcScheme(), cage.mesh.faceSizes[std::size_t(f)]);
            double uv[2] = {points.u[std::size_t(i)], points.v[std::size_t(i)]}, st[2] = {uv[0], uv[1]};
            int sub = 0;
            if (param.HasSubFaces()) sub = param.ConvertCoordToNormalizedSubFace(uv, st);
            const Far::PatchTable::PatchHandle* handle = patches.map->FindPatch(patches.ptexOfFace[f] + sub, st[0], st[1]);
            if (!handle) throw std::runtime_error(cage.mesh.name + ": no patch at a point of face " + std::to_string(f));
            coords[std::size_t(i)] = Osd::PatchCoord(*handle, float(st[0]), float(st[1]));
        }
    }

    void evalPatches(Output& out) {
        const Osd::BufferDescriptor desc(0, 3, 3);
        const int n = points.size();
        du.resize(3 * std::size_t(n));
        dv.resize(du.size());
        Osd::CpuEvaluator::EvalPatches(vertices.data(), desc, out.position.data(), desc, du.data(), desc, dv.data(), desc,
                                       n, coords.data(), patches.cpuTable->GetPatchArrayBuffer(),
                                       patches.cpuTable->GetPatchIndexBuffer(), patches.cpuTable->GetPatchParamBuffer());
        for (std::size_t i = 0; i < std::size_t(n); ++i) unitNormal(&du[3 * i], &dv[3 * i], &out.normal[3 * i]);
    }
};

OsdSurfaceCase::OsdSurfaceCase(const SurfaceCage& cage, OsdScheme scheme, const SurfacePoints& points)
    : s_(std::make_unique<State>(cage, scheme, points)) {}
OsdSurfaceCase::~OsdSurfaceCase() = default;

void OsdSurfaceCase::prepare() {
    State& s = *s_;
    s.refiner = s.newRefiner();
    for (Output* out : {&s.bfrDefault, &s.bfr10, &s.patch, &s.reference}) {
        out->position.assign(3 * std::size_t(s.points.size()), 0.0f);
        out->normal = out->position;
    }
    s.evalBfr(Bfr::RefinerSurfaceFactory<>(*s.refiner, State::bfrOptions(0)), s.bfrDefault);
    s.evalBfr(Bfr::RefinerSurfaceFactory<>(*s.refiner, State::bfrOptions(10)), s.bfr10);
    s.evalBfr<double>(Bfr::RefinerSurfaceFactory<>(*s.refiner, State::bfrOptions(10)), s.reference);
    s.buildPatches(s.patches);
    s.patchVertices();
    s.findPatches();
    s.evalPatches(s.patch);
}

const std::vector<float>& OsdSurfaceCase::referencePositions() const { return s_->reference.position; }
const std::vector<float>& OsdSurfaceCase::referenceNormals() const { return s_->reference.normal; }

std::vector<SurfaceWay> OsdSurfaceCase::measure(int reps) {
    State& s = *s_;
    const double diagonal = s.cage.mesh.boundingBoxDiagonal();
    auto errors = [&](const Output& out, SurfaceWay& way) {
        const InOrderDifference d = compareInOrder(out.position, out.normal, s.reference.position, s.reference.normal);
        way.positionError = d.position / diagonal;
        way.normalError = d.normalAngle;
    };
    std::vector<SurfaceWay> ways;
    for (int approx : {0, 10}) {
        SurfaceWay way;
        way.library = "opensubdiv";
        way.way = approx ? "bfr_approx10" : "bfr_default";
        Output& out = approx ? s.bfr10 : s.bfrDefault;
        way.factoryMs = timeMs(reps, [&] {
            const std::unique_ptr<Far::TopologyRefiner> refiner = s.newRefiner();
            const Bfr::RefinerSurfaceFactory<> factory(*refiner, State::bfrOptions(approx));
        });
        way.pointsMs = timeMs(reps, [&] { s.evalBfr(Bfr::RefinerSurfaceFactory<>(*s.refiner, State::bfrOptions(approx)), out); });
        const Bfr::RefinerSurfaceFactory<> warm(*s.refiner, State::bfrOptions(approx));
        s.evalBfr(warm, out);
        way.warmMs = timeMs(reps, [&] { s.evalBfr(warm, out); });
        errors(out, way);
        ways.push_back(way);
    }
    SurfaceWay way;
    way.library = "opensubdiv";
    way.way = "patch_table_cpu";
    way.factoryMs = timeMs(reps, [&] {
        PatchRoute r;
        s.buildPatches(r);
    });
    way.pointsMs = timeMs(reps, [&] {
        s.patchVertices();
        s.findPatches();
        s.evalPatches(s.patch);
    });
    way.warmMs = timeMs(reps, [&] {
        s.patchVertices();
        s.evalPatches(s.patch);
    });
    errors(s.patch, way);
    ways.push_back(way);
    return ways;
}

}  // namespace quadtri::bench
