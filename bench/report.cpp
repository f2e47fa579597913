#include "bench/report.h"

#include <cstdio>
#include <fstream>
#include <optional>
#include <stdexcept>

namespace quadtri::bench {

namespace {

std::string number(double v, const char* format = "%.6g") {
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

std::string json(std::optional<double> v) { return v ? number(*v) : "null"; }

std::string jsonString(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}

// Milliseconds, bytes and ratios with about three significant digits.
std::string ms(double v) { return number(v, v >= 100 ? "%.0f" : v >= 10 ? "%.1f" : v >= 1 ? "%.2f" : "%.3f"); }
std::string ms(std::optional<double> v) { return v ? ms(*v) : "–"; }
std::string mib(std::size_t bytes) { return ms(double(bytes) / (1 << 20)); }
std::string mib(std::optional<std::size_t> bytes) { return bytes ? mib(*bytes) : "–"; }
std::string json(std::optional<std::size_t> v) { return v ? std::to_string(*v) : "null"; }
std::string ratio(double num, double den) { return den > 0 ? number(num / den, "%.2f") : "–"; }
std::string ratio(double num, std::optional<double> den) { return den ? ratio(num, *den) : "–"; }

void writeLimitJson(std::ostream& f, const std::vector<LimitCaseResult>& cases) {
    f << ",\n  \"limit_cases\": [";
    for (size_t i = 0; i < cases.size(); ++i) {
        const LimitCaseResult& c = cases[i];
        const LimitFigures& q = c.quadtri;
        f << (i ? ",\n" : "\n") << "    {\"mesh\": " << jsonString(c.mesh) << ", \"scheme\": " << jsonString(c.scheme)
          << ", \"level\": " << c.level << ", \"points\": " << c.points << ",\n"
          << "     \"quadtri\": {\"table_bytes\": " << json(q.tableBytes) << ", \"chain_table_bytes\": " << q.chainTableBytes
          << ", \"limit_serial_ms\": " << json(q.limitSerialMs) << ", \"limit_threaded_ms\": " << json(q.limitThreadedMs)
          << ", \"levels_then_limit_serial_ms\": " << number(q.levelsThenLimitSerialMs)
          << ", \"levels_then_limit_threaded_ms\": " << number(q.levelsThenLimitThreadedMs)
          << ", \"mesh_normals_serial_ms\": " << number(q.meshNormalsSerialMs)
          << ", \"mesh_normals_threaded_ms\": " << number(q.meshNormalsThreadedMs)
          << ", \"limit_vulkan_ms\": " << json(q.limitVulkanMs) << "},\n     \"osd\": ";
        if (!c.osd) {
            f << "null, \"ratio_serial\": null, \"ratio_threaded\": null}";
            continue;
        }
        const OsdLimitFigures& o = *c.osd;
        f << "{\"table_bytes\": " << o.tableBytes << ", \"eval_cpu_ms\": " << number(o.evalCpuMs)
          << ", \"eval_omp_ms\": " << number(o.evalOmpMs) << "}, \"ratio_serial\": "
          << number(o.evalCpuMs / q.bestSerialMs()) << ", \"ratio_threaded\": " << number(o.bestMs() / q.bestThreadedMs())
          << "}";
    }
    f << "\n  ]";
}

void printLimitMarkdown(std::ostream& out, const std::vector<LimitCaseResult>& cases) {
    if (cases.empty()) return;
    out << "\nPer-frame limit positions + unit normals of the last level's vertices (qt: factorized limit table /"
           " per-level tables then the limit table over the last level; OSD: Far::LimitStencilTable with du, dv"
           " through Osd::CpuEvaluator / OmpEvaluator, normals in a loop after):\n\n"
        << "| mesh | scheme | L | points | qt MiB | OSD MiB | qt serial ms (fact. / chain) | qt TBB ms (fact. / chain)"
           " | OSD CPU / OMP ms | OSD CPU / qt serial | OSD best / qt TBB | mesh normals serial / TBB ms | qt Vulkan ms |\n"
        << "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const LimitCaseResult& c : cases) {
        const LimitFigures& q = c.quadtri;
        out << "| " << c.mesh << " | " << c.scheme << " | " << c.level << " | " << c.points << " | " << mib(q.tableBytes)
            << " | " << (c.osd ? mib(c.osd->tableBytes) : "–") << " | " << ms(q.limitSerialMs) << " / "
            << ms(q.levelsThenLimitSerialMs) << " | " << ms(q.limitThreadedMs) << " / " << ms(q.levelsThenLimitThreadedMs)
            << " | ";
        if (c.osd)
            out << ms(c.osd->evalCpuMs) << " / " << ms(c.osd->evalOmpMs) << " | " << ratio(c.osd->evalCpuMs, q.bestSerialMs())
                << " | " << ratio(c.osd->bestMs(), q.bestThreadedMs());
        else
            out << "– | – | –";
        out << " | " << ms(q.meshNormalsSerialMs) << " / " << ms(q.meshNormalsThreadedMs) << " | " << ms(q.limitVulkanMs)
            << " |\n";
    }
}

void printCasesMarkdown(std::ostream& out, const BenchResult& r);

}  // namespace

void writeJson(const std::string& path, const BenchResult& r) {
    std::ofstream f(path);
    if (!f) throw std::runtime_error("cannot write " + path);
    f << "{\n  \"memcpy_gbps_1t\": " << number(r.memcpyGbps1) << ",\n  \"memcpy_gbps_2t\": " << number(r.memcpyGbps2)
      << ",\n  \"cases\": [";
    for (size_t i = 0; i < r.cases.size(); ++i) {
        const CaseResult& c = r.cases[i];
        const QuadtriFigures& q = c.quadtri;
        f << (i ? ",\n" : "\n") << "    {\"mesh\": " << jsonString(c.mesh) << ", \"scheme\": " << jsonString(c.scheme)
          << ", \"level\": " << c.level << ", \"refined_vertices\": " << c.refinedVertices << ",\n"
          << "     \"quadtri\": {\"build_ms\": " << number(q.buildMs) << ", \"table_bytes\": " << q.tableBytes
          << ", \"eval_serial_ms\": " << number(q.evalSerialMs) << ", \"eval_threaded_ms\": " << json(q.evalThreadedMs)
          << ", \"eval_vulkan_ms\": " << json(q.evalVulkanMs) << ", \"upload_vulkan_ms\": " << json(q.uploadVulkanMs)
          << "},\n     \"osd\": ";
        if (!c.osd) {
            f << "{\"build_ms_per_level\": null, \"build_ms_factorized\": null, \"eval_cpu_per_level_ms\": null, "
                 "\"eval_cpu_factorized_ms\": null, \"eval_omp_ms\": null, \"table_bytes\": null}}";
            continue;
        }
        const OsdFigures& o = *c.osd;
        f << "{\"build_ms_per_level\": " << number(o.buildMsPerLevel)
          << ", \"build_ms_factorized\": " << number(o.buildMsFactorized)
          << ", \"eval_cpu_per_level_ms\": " << number(o.evalCpuPerLevelMs)
          << ", \"eval_cpu_factorized_ms\": " << number(o.evalCpuFactorizedMs)
          << ", \"eval_omp_ms\": " << number(o.evalOmpMs) << ", \"table_bytes\": " << o.tableBytes << "}}";
    }
    f << "\n  ]";
    writeLimitJson(f, r.limitCases);
    f << "\n}\n";
    if (!f) throw std::runtime_error("cannot write " + path);
}

void printMarkdown(std::ostream& out, const BenchResult& r) {
    if (!r.cases.empty()) printCasesMarkdown(out, r);
    out << "\nmemcpy (" << (r.memcpyBytes >> 20) << " MiB, bytes read + written): " << number(r.memcpyGbps1, "%.1f")
        << " GB/s with 1 thread, " << number(r.memcpyGbps2, "%.1f") << " GB/s with 2 threads\n";
    printLimitMarkdown(out, r.limitCases);
}

namespace {

// One row per case with the main figures and the OSD/quadtri ratios.
void printCasesMarkdown(std::ostream& out, const BenchResult& r) {
    const char* threaded = "TBB";
    out << "| mesh | scheme | L | vertices | qt build ms | OSD build ms (per-level / fact.) | build OSD/qt"
        << " | qt MiB | OSD MiB (per-level / fact.) | bytes qt/OSD | qt serial ms | qt " << threaded << " ms"
        << " | OSD CPU ms (per-level / fact.) | OSD OMP ms | eval OSD best/qt serial | eval OSD best/qt " << threaded
        << " | qt " << threaded << " / memcpy-2t | qt Vulkan eval / upload ms |\n";
    out << "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const CaseResult& c : r.cases) {
        const QuadtriFigures& q = c.quadtri;
        std::string bandwidth = "–";
        if (q.evalThreadedMs && *q.evalThreadedMs > 0 && r.memcpyGbps2 > 0)
            bandwidth = number(100.0 * q.compulsoryBytes / (*q.evalThreadedMs * 1e6) / r.memcpyGbps2, "%.0f%%");
        out << "| " << c.mesh << " | " << c.scheme << " | " << c.level << " | " << c.refinedVertices << " | "
            << ms(q.buildMs) << " | ";
        if (c.osd) {
            const OsdFigures& o = *c.osd;
            out << ms(o.buildMsPerLevel) << " / " << ms(o.buildMsFactorized) << " | " << ratio(o.buildMsPerLevel, q.buildMs)
                << " | " << mib(q.tableBytes) << " | " << mib(o.tableBytes) << " / " << mib(o.tableBytesFactorized)
                << " | " << ratio(double(q.tableBytes), double(o.tableBytes)) << " | " << ms(q.evalSerialMs) << " | "
                << ms(q.evalThreadedMs) << " | " << ms(o.evalCpuPerLevelMs) << " / " << ms(o.evalCpuFactorizedMs)
                << " | " << ms(o.evalOmpMs) << " | " << ratio(o.bestEvalMs(), q.evalSerialMs) << " | "
                << ratio(o.bestEvalMs(), q.evalThreadedMs);
        } else {
            out << "– | – | " << mib(q.tableBytes) << " | – | – | " << ms(q.evalSerialMs) << " | "
                << ms(q.evalThreadedMs) << " | – | – | – | –";
        }
        out << " | " << bandwidth << " | " << ms(q.evalVulkanMs) << " / " << ms(q.uploadVulkanMs) << " |\n";
    }
    out << "Last column: the threaded evaluation's compulsory bytes (all levels' table arrays, distinct source "
           "vertices and output vertices, 12 bytes each) per second, over the 2-thread memcpy bandwidth; above "
           "100% where the working set stays in cache.\n";
}

}  // namespace

}  // namespace quadtri::bench
