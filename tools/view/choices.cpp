#include "tools/view/choices.h"

namespace quadtri::view {

const std::vector<BoundaryInterpolation>& allBoundaries() {
    static const std::vector<BoundaryInterpolation> all{BoundaryInterpolation::EdgeOnly,
                                                        BoundaryInterpolation::EdgeAndCorner, BoundaryInterpolation::None};
    return all;
}

const std::vector<CreaseMethod>& allCreaseMethods() {
    static const std::vector<CreaseMethod> all{CreaseMethod::Uniform, CreaseMethod::Chaikin};
    return all;
}

const std::vector<cli::EvaluatorKind>& allEvaluators() {
    static const std::vector<cli::EvaluatorKind> all{cli::EvaluatorKind::Cpu, cli::EvaluatorKind::Tbb,
                                                     cli::EvaluatorKind::Vulkan};
    return all;
}

const char* toString(cli::EvaluatorKind kind) {
    return kind == cli::EvaluatorKind::Cpu ? "cpu" : kind == cli::EvaluatorKind::Tbb ? "tbb" : "vulkan";
}

const std::vector<render::Shading>& allShadings() {
    static const std::vector<render::Shading> all{render::Shading::Smooth,        render::Shading::Flat,
                                                  render::Shading::ReflectionLines, render::Shading::MeanCurvature,
                                                  render::Shading::FaceType,      render::Shading::Textured};
    return all;
}

const char* toString(render::Shading shading) { return cli::renderShadings().at(std::size_t(shading)).c_str(); }

cli::MeshArgs meshArgsOf(const Choices& choices, Scheme scheme) {
    cli::MeshArgs args;
    args.scheme = scheme;
    args.boundary = choices.boundary;
    args.creaseMethod = choices.creaseMethod;
    args.uvInterpolation = choices.uvs;
    return args;
}

}  // namespace quadtri::view
