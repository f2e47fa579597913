#include "bench/report.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <optional>
#include <stdexcept>

namespace quadtri::bench {

namespace {

std::string number(double v, const char* format = "%.6g") {
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

std::string jsonString(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}

std::string json(const Timing& t) {
    return "{\"median\": " + number(t.median) + ", \"min\": " + number(t.min) + ", \"max\": " + number(t.max) + "}";
}
std::string json(const std::optional<Timing>& t) { return t ? json(*t) : "null"; }
std::string json(std::optional<std::size_t> v) { return v ? std::to_string(*v) : "null"; }
std::string json(const MemoryFigures& m) {
    return "{\"table_bytes\": " + std::to_string(m.tableBytes) + ", \"buffer_bytes\": " + std::to_string(m.bufferBytes) +
           ", \"peak_resident_bytes\": " + json(m.peakResidentBytes) + "}";
}
std::string json(const MemcpyFigures& m) {
    return "{\"bytes\": " + std::to_string(m.bytes) + ", \"gbps_1t\": " + number(m.gbps1) +
           ", \"gbps_all\": " + number(m.gbpsAll) + "}";
}

// Milliseconds, bytes and ratios with about three significant digits.
std::string ms(double v) { return number(v, v >= 100 ? "%.0f" : v >= 10 ? "%.1f" : v >= 1 ? "%.2f" : "%.3f"); }
std::string ms(const std::optional<Timing>& v) { return v ? ms(v->median) : "–"; }
std::string mib(std::size_t bytes) { return ms(double(bytes) / (1 << 20)); }
std::string mib(std::optional<std::size_t> bytes) { return bytes ? mib(*bytes) : "–"; }
std::string ratio(double num, double den) { return den > 0 ? number(num / den, "%.2f") : "–"; }

// OpenSubdiv's fastest evaluation of a case: on its serial ways only (Osd::CpuEvaluator and
// Far's UpdateValues, as bench/performance_section.py counts them), or on any.
double osdBest(const OsdFigures& o, bool serialOnly, std::optional<int> width = std::nullopt) {
    double best = std::numeric_limits<double>::infinity();
    for (const OsdEvaluation& e : o.evaluations)
        if ((!serialOnly || e.evaluator == "cpu" || e.evaluator == "far") && (!width || e.width == *width))
            best = std::min(best, e.ms.median);
    return best;
}

void writeCaseJson(std::ostream& f, const CaseResult& c) {
    const QuadtriFigures& q = c.quadtri;
    f << "    {\"mesh\": " << jsonString(c.mesh) << ", \"scheme\": " << jsonString(c.scheme) << ", \"level\": " << c.level
      << ", \"refined_vertices\": " << c.refinedVertices << ",\n     \"memcpy_working_set\": " << json(c.memcpyWorkingSet)
      << ",\n     \"quadtri\": {\"build_1t_ms\": " << json(q.build1Ms) << ", \"build_ms\": " << json(q.buildMs)
      << ",\n       \"build_factorized_1t_ms\": " << json(q.buildFactorized1Ms)
      << ", \"build_factorized_ms\": " << json(q.buildFactorizedMs)
      << ",\n       \"table_bytes\": " << q.tableBytes << ", \"compulsory_bytes\": " << number(q.compulsoryBytes, "%.0f")
      << ", \"compulsory_bytes_4f\": " << number(q.compulsoryBytes4, "%.0f")
      << ",\n       \"eval_serial_ms\": " << json(q.evalSerialMs) << ",\n       \"eval_threaded_ms\": "
      << json(q.evalThreadedMs) << ",\n       \"eval_serial_4f_ms\": " << json(q.evalSerial4Ms)
      << ",\n       \"eval_threaded_4f_ms\": " << json(q.evalThreaded4Ms) << ",\n       \"eval_vulkan_ms\": "
      << json(q.evalVulkanMs) << ", \"upload_vulkan_ms\": " << json(q.uploadVulkanMs)
      << ",\n       \"memory\": " << json(q.memory) << "},\n     \"osd\": ";
    if (!c.osd) {
        f << "null}";
        return;
    }
    const OsdFigures& o = *c.osd;
    f << "{\"build_per_level_ms\": " << json(o.buildPerLevelMs) << ", \"build_factorized_ms\": "
      << json(o.buildFactorizedMs) << ",\n       \"table_bytes\": " << o.tableBytes
      << ", \"table_bytes_factorized\": " << o.tableBytesFactorized << ", \"evaluations\": [";
    for (std::size_t i = 0; i < o.evaluations.size(); ++i) {
        const OsdEvaluation& e = o.evaluations[i];
        f << (i ? "," : "") << "\n         {\"table\": " << jsonString(e.table) << ", \"evaluator\": "
          << jsonString(e.evaluator) << ", \"width\": " << e.width << ", \"ms\": " << json(e.ms) << "}";
    }
    f << "],\n       \"memory\": " << json(o.memory) << "}}";
}

void writeLimitCaseJson(std::ostream& f, const LimitCaseResult& c) {
    const LimitFigures& q = c.quadtri;
    f << "    {\"mesh\": " << jsonString(c.mesh) << ", \"scheme\": " << jsonString(c.scheme) << ", \"level\": " << c.level
      << ", \"points\": " << c.points << ",\n     \"quadtri\": {\"table_bytes\": " << json(q.tableBytes)
      << ", \"chain_table_bytes\": " << q.chainTableBytes << ",\n       \"limit_serial_ms\": " << json(q.limitSerialMs)
      << ",\n       \"limit_threaded_ms\": " << json(q.limitThreadedMs)
      << ",\n       \"levels_then_limit_serial_ms\": " << json(q.levelsThenLimitSerialMs)
      << ",\n       \"levels_then_limit_threaded_ms\": " << json(q.levelsThenLimitThreadedMs)
      << ",\n       \"mesh_normals_serial_ms\": " << json(q.meshNormalsSerialMs)
      << ",\n       \"mesh_normals_threaded_ms\": " << json(q.meshNormalsThreadedMs)
      << ",\n       \"limit_vulkan_ms\": " << json(q.limitVulkanMs) << ",\n       \"memory\": " << json(q.memory)
      << "},\n     \"osd\": ";
    if (!c.osd) {
        f << "null}";
        return;
    }
    const OsdLimitFigures& o = *c.osd;
    f << "{\"table_bytes\": " << o.tableBytes << ", \"eval_cpu_ms\": " << json(o.evalCpuMs)
      << ", \"eval_omp_ms\": " << json(o.evalOmpMs) << ", \"eval_far_ms\": " << json(o.evalFarMs)
      << ",\n       \"memory\": " << json(o.memory) << "}}";
}

double bestSerial(const LimitFigures& q) {
    return std::min(q.limitSerialMs ? q.limitSerialMs->median : q.levelsThenLimitSerialMs.median,
                    q.levelsThenLimitSerialMs.median);
}
double bestThreaded(const LimitFigures& q) {
    return std::min(q.limitThreadedMs ? q.limitThreadedMs->median : q.levelsThenLimitThreadedMs.median,
                    q.levelsThenLimitThreadedMs.median);
}

void printLimitMarkdown(std::ostream& out, const std::vector<LimitCaseResult>& cases) {
    if (cases.empty()) return;
    out << "\nPer-frame limit positions + unit normals of the last level's vertices (qt: factorized limit table /"
           " per-level tables then the limit table over the last level; OSD: Far::LimitStencilTable with du, dv"
           " through Osd::CpuEvaluator / OmpEvaluator / Far's UpdateValues + UpdateDerivs, normals in a loop after;"
           " 3 floats):\n\n"
        << "| mesh | scheme | L | points | qt MiB | OSD MiB | qt serial ms (fact. / chain) | qt TBB ms (fact. / chain)"
           " | OSD CPU / OMP / Far ms | OSD serial / qt serial | OSD best / qt TBB | mesh normals serial / TBB ms"
           " | qt Vulkan ms |\n"
        << "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const LimitCaseResult& c : cases) {
        const LimitFigures& q = c.quadtri;
        out << "| " << c.mesh << " | " << c.scheme << " | " << c.level << " | " << c.points << " | " << mib(q.tableBytes)
            << " | " << (c.osd ? mib(c.osd->tableBytes) : "–") << " | " << ms(q.limitSerialMs) << " / "
            << ms(q.levelsThenLimitSerialMs.median) << " | " << ms(q.limitThreadedMs) << " / "
            << ms(q.levelsThenLimitThreadedMs.median) << " | ";
        if (c.osd) {
            const OsdLimitFigures& o = *c.osd;
            const double serialMs = std::min(o.evalCpuMs.median, o.evalFarMs.median);
            out << ms(o.evalCpuMs.median) << " / " << ms(o.evalOmpMs.median) << " / " << ms(o.evalFarMs.median) << " | "
                << ratio(serialMs, bestSerial(q)) << " | " << ratio(std::min(serialMs, o.evalOmpMs.median), bestThreaded(q));
        } else {
            out << "– | – | –";
        }
        out << " | " << ms(q.meshNormalsSerialMs.median) << " / " << ms(q.meshNormalsThreadedMs.median) << " | "
            << ms(q.limitVulkanMs) << " |\n";
    }
}

// One row per case: builds and evaluations side by side, like for like (serial against
// OpenSubdiv's serial, all threads against its best on any evaluator), and the share of memcpy
// bandwidth the evaluation reaches.
void printCasesMarkdown(std::ostream& out, const BenchResult& r) {
    out << "| mesh | scheme | L | vertices | qt build ms 1t / " << r.threads << "t | OSD build ms (per-level / fact.)"
        << " | build OSD/qt 1t | qt fact. build ms 1t / " << r.threads << "t | fact. build OSD/qt 1t | qt MiB | OSD MiB (per-level / fact.) | qt eval ms serial / TBB (3f)"
        << " | OSD best ms serial 4f / 3f / any | eval OSD/qt serial | eval OSD/qt TBB"
        << " | qt TBB / memcpy (working set) | peak MiB qt / OSD | qt Vulkan eval / upload ms |\n";
    out << "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const CaseResult& c : r.cases) {
        const QuadtriFigures& q = c.quadtri;
        std::string bandwidth = "–";
        if (q.evalThreadedMs.median > 0 && c.memcpyWorkingSet.gbpsAll > 0)
            bandwidth = number(100.0 * q.compulsoryBytes / (q.evalThreadedMs.median * 1e6) / c.memcpyWorkingSet.gbpsAll,
                               "%.0f%%");
        out << "| " << c.mesh << " | " << c.scheme << " | " << c.level << " | " << c.refinedVertices << " | "
            << ms(q.build1Ms.median) << " / " << ms(q.buildMs.median) << " | ";
        if (c.osd) {
            const OsdFigures& o = *c.osd;
            out << ms(o.buildPerLevelMs.median) << " / " << ms(o.buildFactorizedMs.median) << " | "
                << ratio(std::min(o.buildPerLevelMs.median, o.buildFactorizedMs.median), q.build1Ms.median) << " | "
                << ms(q.buildFactorized1Ms) << " / " << ms(q.buildFactorizedMs) << " | "
                << (q.buildFactorized1Ms ? ratio(o.buildFactorizedMs.median, q.buildFactorized1Ms->median) : "–") << " | "
                << mib(q.tableBytes) << " | " << mib(o.tableBytes) << " / " << mib(o.tableBytesFactorized) << " | "
                << ms(q.evalSerialMs.median) << " / " << ms(q.evalThreadedMs.median) << " | "
                << ms(osdBest(o, true, 4)) << " / " << ms(osdBest(o, true, 3)) << " / " << ms(osdBest(o, false)) << " | "
                << ratio(osdBest(o, true), q.evalSerialMs.median) << " | "
                << ratio(osdBest(o, false), q.evalThreadedMs.median);
        } else {
            out << "– | – | " << ms(q.buildFactorized1Ms) << " / " << ms(q.buildFactorizedMs) << " | – | " << mib(q.tableBytes) << " | – | " << ms(q.evalSerialMs.median) << " / "
                << ms(q.evalThreadedMs.median) << " | – | – | –";
        }
        out << " | " << bandwidth << " | " << mib(q.memory.peakResidentBytes) << " / "
            << (c.osd ? mib(c.osd->memory.peakResidentBytes) : "–") << " | " << ms(q.evalVulkanMs) << " / "
            << ms(q.uploadVulkanMs) << " |\n";
    }
    out << "Bandwidth column: the threaded evaluation's compulsory bytes (all levels' table arrays, distinct source "
           "vertices and output vertices, 12 bytes each) per second, over the all-thread memcpy bandwidth of a copy "
           "whose source and destination together are that size.\n";
}

void writeFrameTimingsJson(std::ostream& f, const std::vector<FrameTiming>& timings) {
    f << "[";
    for (std::size_t i = 0; i < timings.size(); ++i) {
        const FrameTiming& t = timings[i];
        f << (i ? "," : "") << "\n       {\"evaluator\": " << jsonString(t.evaluator) << ", \"route\": " << jsonString(t.route)
          << ", \"fps\": " << number(1000.0 / t.frameMs.median) << ", \"frame_ms\": " << json(t.frameMs)
          << ",\n        \"deform_ms\": " << json(t.deformMs) << ", \"evaluate_ms\": " << json(t.evaluateMs)
          << ", \"normals_ms\": " << json(t.normalsMs) << "}";
    }
    f << "]";
}

void writeFrameCaseJson(std::ostream& f, const FrameCaseResult& c) {
    f << "    {\"mesh\": " << jsonString(c.mesh) << ", \"scheme\": " << jsonString(c.scheme) << ", \"level\": " << c.level
      << ", \"control_vertices\": " << c.controlVertices << ", \"faces\": " << c.faces << ", \"points\": " << c.points
      << ", \"frames\": " << c.frames << ",\n     \"limit_table_bytes\": " << json(c.limitTableBytes)
      << ", \"chain_table_bytes\": " << c.chainTableBytes << ",\n     \"quadtri\": ";
    writeFrameTimingsJson(f, c.quadtri);
    f << ",\n     \"osd\": ";
    if (c.osd.empty()) f << "null";
    else writeFrameTimingsJson(f, c.osd);
    f << "}";
}

// The fastest of `timings` on one of `evaluators` whose route is a limit route (or, with
// meshNormals, the mesh-normal route); null if none.
const FrameTiming* fastestFrame(const std::vector<FrameTiming>& timings, std::initializer_list<const char*> evaluators,
                                bool meshNormals = false) {
    const FrameTiming* best = nullptr;
    for (const FrameTiming& t : timings) {
        if ((t.route == "levels_then_mesh_normals") != meshNormals) continue;
        if (std::none_of(evaluators.begin(), evaluators.end(), [&](const char* e) { return t.evaluator == e; })) continue;
        if (!best || t.frameMs.median < best->frameMs.median) best = &t;
    }
    return best;
}

std::string frameCell(const FrameTiming* t, bool withRoute = true) {
    if (!t) return "– | –";
    return ms(t->frameMs.median) + (withRoute ? " (" + t->route + ")" : "") + " | " +
           number(1000.0 / t->frameMs.median, "%.1f");
}

// Per cage, level and quadtri evaluator: its fastest limit frame, OpenSubdiv's fastest like for
// like (serial against its serial ways, threaded and Vulkan against any), the ratio, and the
// mesh-normal frame.
void printFramesMarkdown(std::ostream& out, const std::vector<FrameCaseResult>& cases) {
    if (cases.empty()) return;
    out << "The whole frame: the cage posed by the two-bone skin, then level N's limit positions + unit normals"
           " (qt: its faster table route; OSD: Far::LimitStencilTable with du, dv, then normalize(du x dv), on the"
           " same posed cage), and qt's refined positions + mesh normals (per-level tables, then EvalMeshNormals):\n\n"
        << "| mesh | scheme | L | points | evaluator | qt limit frame ms (route) | fps | OSD frame ms (evaluator) | fps"
           " | OSD / qt | qt mesh-normal frame ms | fps |\n"
        << "|---|---|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const FrameCaseResult& c : cases)
        for (const char* evaluator : {"cpu", "tbb", "vulkan"}) {
            const FrameTiming* q = fastestFrame(c.quadtri, {evaluator});
            if (!q) continue;
            const bool serial = !std::strcmp(evaluator, "cpu");
            const FrameTiming* o = serial ? fastestFrame(c.osd, {"cpu", "far"}) : fastestFrame(c.osd, {"cpu", "omp", "far"});
            out << "| " << c.mesh << " | " << c.scheme << " | " << c.level << " | " << c.points << " | " << evaluator
                << " | " << frameCell(q) << " | ";
            if (o) out << ms(o->frameMs.median) << " (" << o->evaluator << ") | " << number(1000.0 / o->frameMs.median, "%.1f")
                       << " | " << ratio(o->frameMs.median, q->frameMs.median);
            else out << "– | – | –";
            out << " | " << frameCell(fastestFrame(c.quadtri, {evaluator}, true), false) << " |\n";
        }
    out << "\n";
}

std::string json(const std::optional<double>& v) { return v ? number(*v) : "null"; }

void writeSurfaceCaseJson(std::ostream& f, const SurfaceCaseResult& c) {
    f << "    {\"mesh\": " << jsonString(c.mesh) << ", \"scheme\": " << jsonString(c.scheme) << ", \"faces\": " << c.faces
      << ", \"points\": " << c.points << ",\n     \"ways\": [";
    for (std::size_t i = 0; i < c.ways.size(); ++i) {
        const SurfaceWay& w = c.ways[i];
        f << (i ? ",\n" : "\n") << "       {\"library\": " << jsonString(w.library) << ", \"way\": " << jsonString(w.way)
          << ", \"factory_ms\": " << json(w.factoryMs) << ",\n        \"points_ms\": " << json(w.pointsMs)
          << ", \"warm_ms\": " << json(w.warmMs) << ",\n        \"position_error\": " << json(w.positionError)
          << ", \"normal_error\": " << json(w.normalError) << "}";
    }
    f << "]}";
}

// Per case and way: the factory, microseconds a point (a new factory, then the caches full) and
// the errors against Bfr at level 10; the ratios OpenSubdiv's way / quadtri's.
void printSurfaceMarkdown(std::ostream& out, const std::vector<SurfaceCaseResult>& cases) {
    if (cases.empty()) return;
    out << "\nSurface evaluation at random (u, v) on every face, serial: position, du, dv, unit normal (µs a point:"
           " a new factory / its caches full; errors against Bfr at approximation level 10, of the diagonal and in"
           " rad; ×: OpenSubdiv's time / quadtri's)\n\n"
        << "| mesh | scheme | points | way | factory ms | µs/point | warm µs/point | position error | normal error |"
           " × factory | × points | × warm |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const SurfaceCaseResult& c : cases) {
        const SurfaceWay& q = c.ways.front();
        auto perPoint = [&](double msAll) { return number(1000.0 * msAll / c.points, "%.3f"); };
        for (const SurfaceWay& w : c.ways) {
            const bool peer = &w != &q;
            out << "| " << c.mesh << " | " << c.scheme << " | " << c.points << " | " << w.library << " " << w.way << " | "
                << ms(w.factoryMs.median) << " | " << perPoint(w.pointsMs.median) << " | "
                << (w.warmMs ? perPoint(w.warmMs->median) : "–") << " | "
                << (w.positionError ? number(*w.positionError, "%.1e") : "–") << " | "
                << (w.normalError ? number(*w.normalError, "%.1e") : "–") << " | "
                << (peer ? ratio(w.factoryMs.median, q.factoryMs.median) : "") << " | "
                << (peer ? ratio(w.pointsMs.median, q.pointsMs.median) : "") << " | "
                << (peer && w.warmMs && q.warmMs ? ratio(w.warmMs->median, q.warmMs->median) : "") << " |\n";
        }
    }
}

void writeTessellationCaseJson(std::ostream& f, const TessellationCaseResult& c) {
    f << "    {\"mesh\": " << jsonString(c.mesh) << ", \"scheme\": " << jsonString(c.scheme) << ", \"faces\": " << c.faces
      << ", \"rate\": " << c.rate << ",\n     \"ways\": [";
    for (std::size_t i = 0; i < c.ways.size(); ++i) {
        const TessellationWay& w = c.ways[i];
        f << (i ? ",\n" : "\n") << "       {\"library\": " << jsonString(w.library) << ", \"way\": " << jsonString(w.way)
          << ", \"points\": " << w.points << ", \"triangles\": " << w.triangles << ",\n        \"first_ms\": "
          << json(w.firstMs) << ", \"frame_ms\": " << json(w.frameMs) << ", \"area\": " << number(w.area) << "}";
    }
    f << "]}";
}

// Per case and way: points, triangles, the first tessellation and a frame's; the ratios
// OpenSubdiv's time / quadtri's.
void printTessellationMarkdown(std::ostream& out, const std::vector<TessellationCaseResult>& cases) {
    if (cases.empty()) return;
    out << "\nTessellation of every face at a uniform rate, serial: points, unit normals and triangles (first: from"
           " the mesh's arrays; frame: the cage moved; ×: OpenSubdiv's time / quadtri's)\n\n"
        << "| mesh | scheme | rate | way | points | triangles | first ms | frame ms | × first | × frame |\n"
           "|---|---|---|---|---|---|---|---|---|---|\n";
    for (const TessellationCaseResult& c : cases) {
        const TessellationWay& q = c.ways.front();
        for (const TessellationWay& w : c.ways) {
            const bool peer = &w != &q;
            out << "| " << c.mesh << " | " << c.scheme << " | " << c.rate << " | " << w.library << " " << w.way << " | "
                << w.points << " | " << w.triangles << " | " << ms(w.firstMs.median) << " | " << ms(w.frameMs.median)
                << " | " << (peer ? ratio(w.firstMs.median, q.firstMs.median) : "") << " | "
                << (peer ? ratio(w.frameMs.median, q.frameMs.median) : "") << " |\n";
        }
    }
}

void writeEditCaseJson(std::ostream& f, const EditCaseResult& c) {
    f << "    {\"mesh\": " << jsonString(c.mesh) << ", \"scheme\": " << jsonString(c.scheme) << ", \"level\": " << c.level
      << ", \"edit\": " << jsonString(c.edit) << ", \"points\": " << c.points << ", \"stencils_written\": " << c.stencilsWritten
      << ",\n     \"update_ms\": " << json(c.updateMs) << ", \"rebuild_ms\": " << json(c.rebuildMs)
      << ", \"max_difference\": " << number(c.maxDifference) << ",\n     \"osd_scheme\": "
      << (c.osdScheme.empty() ? "null" : jsonString(c.osdScheme)) << ", \"osd_rebuild_ms\": " << json(c.osdRebuildMs) << "}";
}

// Per edit: the update, the rebuild and OpenSubdiv's rebuild, and how many times faster.
void printEditMarkdown(std::ostream& out, const std::vector<EditCaseResult>& cases) {
    if (cases.empty()) return;
    out << "\nEdits in place (Refiner::applyEdits + LimitTableUpdate of the factorized limit table) against the same"
           " tables built again, all threads; OpenSubdiv's rebuild serial\n\n"
        << "| mesh | scheme | L | edit | points | written | update ms | rebuild ms | × | max difference | OSD rebuild ms"
           " | × OSD |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const EditCaseResult& c : cases)
        out << "| " << c.mesh << " | " << c.scheme << " | " << c.level << " | " << c.edit << " | " << c.points << " | "
            << c.stencilsWritten << " | " << ms(c.updateMs.median) << " | " << ms(c.rebuildMs.median) << " | "
            << ratio(c.rebuildMs.median, c.updateMs.median) << " | " << number(c.maxDifference, "%.1e") << " | "
            << ms(c.osdRebuildMs) << " | " << (c.osdRebuildMs ? ratio(c.osdRebuildMs->median, c.updateMs.median) : "–")
            << " |\n";
}

}  // namespace

void writeJson(const std::string& path, const BenchResult& r) {
    std::ofstream f(path);
    if (!f) throw std::runtime_error("cannot write " + path);
    f << "{\n  \"date\": " << jsonString(r.date) << ", \"cpu\": " << jsonString(r.cpu) << ",\n  \"command\": "
      << jsonString(r.command) << ", \"repetitions\": " << r.repetitions << ", \"threads\": " << r.threads
      << ", \"vulkan_device\": " << (r.vulkanDevice.empty() ? "null" : jsonString(r.vulkanDevice))
      << ",\n  \"memcpy\": " << json(r.memcpyLarge)
      << ",\n  \"cases\": [";
    for (std::size_t i = 0; i < r.cases.size(); ++i) {
        f << (i ? ",\n" : "\n");
        writeCaseJson(f, r.cases[i]);
    }
    f << "\n  ],\n  \"frame_cases\": [";
    for (std::size_t i = 0; i < r.frameCases.size(); ++i) {
        f << (i ? ",\n" : "\n");
        writeFrameCaseJson(f, r.frameCases[i]);
    }
    f << "\n  ],\n  \"limit_cases\": [";
    for (std::size_t i = 0; i < r.limitCases.size(); ++i) {
        f << (i ? ",\n" : "\n");
        writeLimitCaseJson(f, r.limitCases[i]);
    }
    f << "\n  ],\n  \"surface_cases\": [";
    for (std::size_t i = 0; i < r.surfaceCases.size(); ++i) {
        f << (i ? ",\n" : "\n");
        writeSurfaceCaseJson(f, r.surfaceCases[i]);
    }
    f << "\n  ],\n  \"tessellation_cases\": [";
    for (std::size_t i = 0; i < r.tessellationCases.size(); ++i) {
        f << (i ? ",\n" : "\n");
        writeTessellationCaseJson(f, r.tessellationCases[i]);
    }
    f << "\n  ],\n  \"edit_cases\": [";
    for (std::size_t i = 0; i < r.editCases.size(); ++i) {
        f << (i ? ",\n" : "\n");
        writeEditCaseJson(f, r.editCases[i]);
    }
    f << "\n  ]\n}\n";
    if (!f) throw std::runtime_error("cannot write " + path);
}

void printMarkdown(std::ostream& out, const BenchResult& r) {
    printFramesMarkdown(out, r.frameCases);
    if (!r.cases.empty()) printCasesMarkdown(out, r);
    out << "\nmemcpy (" << (r.memcpyLarge.bytes >> 20) << " MiB, bytes read + written): "
        << number(r.memcpyLarge.gbps1, "%.1f") << " GB/s with 1 thread, " << number(r.memcpyLarge.gbpsAll, "%.1f")
        << " GB/s with " << r.threads << "\n";
    printLimitMarkdown(out, r.limitCases);
    printSurfaceMarkdown(out, r.surfaceCases);
    printTessellationMarkdown(out, r.tessellationCases);
    printEditMarkdown(out, r.editCases);
}

}  // namespace quadtri::bench
