#!/usr/bin/env python3
"""Writes the measured performance figures from a quadtri-bench JSON file: every figure into
docs/performance.md, and a headline table of a few rows into README.md.

    build/bin/quadtri-bench --json bench.json
    python3 bench/performance_section.py bench.json --readme README.md --doc docs/performance.md [--note TEXT]

Each file has its own pair of marker lines (BEGIN / END for the figures, HEADLINE_BEGIN /
HEADLINE_END for the README's table); what lies between them is replaced, so rerunning it after a
new bench run replaces the section and never appends. Every number written comes from the JSON;
ratios are OpenSubdiv / quadtri (higher is better for quadtri), each stated like for like:
threads, table kind and floats a vertex. The whole frame comes first (the goal's figures, then a
row per cage, level and evaluator). Standard library only.
"""

import argparse
import json
import sys

BEGIN = "<!-- performance-figures:begin (written by bench/performance_section.py; edits here are overwritten) -->"
END = "<!-- performance-figures:end -->"
HEADLINE_BEGIN = "<!-- performance-headline:begin (written by bench/performance_section.py; edits here are overwritten) -->"
HEADLINE_END = "<!-- performance-headline:end -->"
COMMAND = "python3 bench/performance_section.py bench.json --readme README.md --doc docs/performance.md"


def fmt(v):
    """About three significant digits, as the bench prints them."""
    if v is None:
        return "–"
    a = abs(v)
    if a >= 100:
        return f"{v:.0f}"
    if a >= 10:
        return f"{v:.1f}"
    if a >= 1:
        return f"{v:.2f}"
    return f"{v:.3f}"


def timing(t):
    """median (min–max) of one figure's repetitions."""
    if t is None:
        return "–"
    return f"{fmt(t['median'])} ({fmt(t['min'])}–{fmt(t['max'])})"


def ratio(num, den):
    return f"{num / den:.2f}" if num is not None and den else "–"


def mib(b):
    return fmt(b / 2**20) if b is not None else "–"


def pct(v):
    return f"{100 * v:.0f} %" if v is not None else "–"


def span(values):
    """'a–b' over a list of numbers (empty: '–')."""
    values = [v for v in values if v is not None]
    if not values:
        return "–"
    lo, hi = min(values), max(values)
    return f"{lo:.2f}" if f"{lo:.2f}" == f"{hi:.2f}" else f"{lo:.2f}–{hi:.2f}"


def case_label(c):
    return f"{c['mesh']} | {c['scheme']} | {c['level']}"


SERIAL = ("cpu", "far")  # Osd::CpuEvaluator, Far::StencilTable::UpdateValues


def osd_best(osd, evaluators=None, width=None):
    """OpenSubdiv's fastest evaluation among those that match, as (evaluation, median ms)."""
    ways = [e for e in osd["evaluations"]
            if (evaluators is None or e["evaluator"] in evaluators) and (width is None or e["width"] == width)]
    best = min(ways, key=lambda e: e["ms"]["median"])
    return best, best["ms"]["median"]


def way_name(e):
    table = "per-level" if e["table"] == "per_level" else "factorized"
    evaluator = {"cpu": "CpuEvaluator", "omp": "OmpEvaluator", "far": "Far UpdateValues"}[e["evaluator"]]
    return f"{evaluator}, {table}, {e['width']}f"


def gbps(bytes_moved, ms):
    return bytes_moved / (ms * 1e6) if ms else None


def serial_table(r):
    rows = ["| mesh | scheme | L | vertices | quadtri 3f ms | quadtri 4f ms | OSD best serial 4f ms | OSD best serial 3f ms"
            " | OSD 4f / quadtri 3f | OSD 4f / quadtri 4f | OSD 3f / quadtri 3f | quadtri 3f / memcpy 1t (working set, 256 MiB) |",
            "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for c in r["cases"]:
        q, o = c["quadtri"], c["osd"]
        rate = gbps(q["compulsory_bytes"], q["eval_serial_ms"]["median"])
        share = (f"{pct(rate / c['memcpy_working_set']['gbps_1t'])}, {pct(rate / r['memcpy']['gbps_1t'])}")
        if o:
            b4, m4 = osd_best(o, SERIAL, 4)
            b3, m3 = osd_best(o, SERIAL, 3)
            osd_cols = (f"{timing(b4['ms'])}, {way_name(b4)} | {timing(b3['ms'])}, {way_name(b3)} | "
                        f"{ratio(m4, q['eval_serial_ms']['median'])} | "
                        f"{ratio(m4, q['eval_serial_4f_ms']['median'])} | {ratio(m3, q['eval_serial_ms']['median'])}")
        else:
            osd_cols = "– | – | – | – | –"
        rows.append(f"| {case_label(c)} | {c['refined_vertices']} | {timing(q['eval_serial_ms'])} | "
                    f"{timing(q['eval_serial_4f_ms'])} | {osd_cols} | {share} |")
    return rows


def threaded_table(r):
    n = r["threads"]
    rows = [f"| mesh | scheme | L | quadtri TBB 3f ms | quadtri TBB 4f ms | OSD best ms, any evaluator | OSD best / quadtri 3f"
            f" | OSD best / quadtri 4f | quadtri 3f GB/s | / memcpy {n}t working set | / memcpy {n}t 256 MiB |",
            "|---|---|---:|---:|---:|---|---:|---:|---:|---:|---:|"]
    for c in r["cases"]:
        q, o = c["quadtri"], c["osd"]
        rate = gbps(q["compulsory_bytes"], q["eval_threaded_ms"]["median"])
        if o:
            b, m = osd_best(o)
            osd_cols = (f"{timing(b['ms'])}, {way_name(b)} | {ratio(m, q['eval_threaded_ms']['median'])} | "
                        f"{ratio(m, q['eval_threaded_4f_ms']['median'])}")
        else:
            osd_cols = "– | – | –"
        rows.append(f"| {case_label(c)} | {timing(q['eval_threaded_ms'])} | {timing(q['eval_threaded_4f_ms'])} | "
                    f"{osd_cols} | {rate:.1f} | {pct(rate / c['memcpy_working_set']['gbps_all'])} | "
                    f"{pct(rate / r['memcpy']['gbps_all'])} |")
    return rows


def median(t):
    return t["median"] if t else None


def build_table(r):
    n = r["threads"]
    rows = [f"| mesh | scheme | L | quadtri 1t ms | quadtri {n}t ms | OSD per-level ms | OSD factorized ms"
            f" | OSD best / quadtri 1t | OSD best / quadtri {n}t |",
            "|---|---|---:|---:|---:|---:|---:|---:|---:|"]
    for c in r["cases"]:
        q, o = c["quadtri"], c["osd"]
        if o:
            best = min(o["build_per_level_ms"]["median"], o["build_factorized_ms"]["median"])
            osd_cols = (f"{timing(o['build_per_level_ms'])} | {timing(o['build_factorized_ms'])} | "
                        f"{ratio(best, q['build_1t_ms']['median'])} | {ratio(best, q['build_ms']['median'])}")
        else:
            osd_cols = "– | – | – | –"
        rows.append(f"| {case_label(c)} | {timing(q['build_1t_ms'])} | {timing(q['build_ms'])} | {osd_cols} |")
    return rows


def factorized_build_table(r):
    n = r["threads"]
    rows = [f"| mesh | scheme | L | quadtri factorized 1t ms | quadtri factorized {n}t ms | OSD factorized ms"
            f" | OSD / quadtri 1t | quadtri factorized / per-level, 1t |",
            "|---|---|---:|---:|---:|---:|---:|---:|"]
    for c in [c for c in r["cases"] if c["quadtri"].get("build_factorized_1t_ms")]:
        q, o = c["quadtri"], c["osd"]
        fact1 = median(q.get("build_factorized_1t_ms"))
        osd_cols = (f"{timing(o['build_factorized_ms'])} | {ratio(o['build_factorized_ms']['median'], fact1)}"
                    if o else "– | –")
        rows.append(f"| {case_label(c)} | {timing(q.get('build_factorized_1t_ms'))} | "
                    f"{timing(q.get('build_factorized_ms'))} | {osd_cols} | {ratio(fact1, q['build_1t_ms']['median'])} |")
    return rows


def memory_table(r):
    rows = ["| mesh | scheme | L | quadtri tables MiB | OSD per-level / factorized MiB | tables quadtri / OSD per-level"
            " | 3f buffers MiB | quadtri peak MiB | OSD peak MiB |",
            "|---|---|---:|---:|---:|---:|---:|---:|---:|"]
    for c in r["cases"]:
        q, o = c["quadtri"], c["osd"]
        osd_tables = f"{mib(o['table_bytes'])} / {mib(o['table_bytes_factorized'])}" if o else "–"
        rows.append(f"| {case_label(c)} | {mib(q['table_bytes'])} | {osd_tables} | "
                    f"{ratio(q['table_bytes'], o['table_bytes']) if o else '–'} | "
                    f"{mib(q['memory']['buffer_bytes'])} | {mib(q['memory']['peak_resident_bytes'])} | "
                    f"{mib(o['memory']['peak_resident_bytes']) if o else '–'} |")
    return rows


def vulkan_table(r):
    rows = ["| mesh | scheme | L | Vulkan eval ms (all levels, submit to fence) | upload ms (tables + control) | quadtri TBB 3f ms |",
            "|---|---|---:|---:|---:|---:|"]
    for c in r["cases"]:
        q = c["quadtri"]
        if q["eval_vulkan_ms"]:
            rows.append(f"| {case_label(c)} | {timing(q['eval_vulkan_ms'])} | {timing(q['upload_vulkan_ms'])} | "
                        f"{fmt(q['eval_threaded_ms']['median'])} |")
    return rows if len(rows) > 2 else []


def limit_best(q, threaded):
    chain = q["levels_then_limit_threaded_ms" if threaded else "levels_then_limit_serial_ms"]["median"]
    fact = q["limit_threaded_ms" if threaded else "limit_serial_ms"]
    return min(chain, fact["median"]) if fact else chain


def osd_limit_best(o, serial):
    """OpenSubdiv's fastest limit evaluation: serial (CpuEvaluator, Far's templates) or on any evaluator."""
    keys = ["eval_cpu_ms", "eval_far_ms"] + ([] if serial else ["eval_omp_ms"])
    return min(o[k]["median"] for k in keys)


def limit_table(r):
    rows = ["| mesh | scheme | L | points | quadtri table MiB / OSD | quadtri serial ms, factorized / chain"
            " | quadtri TBB ms, factorized / chain | OSD CpuEvaluator ms | OSD OmpEvaluator ms | OSD Far ms"
            " | OSD best serial / quadtri serial"
            " | OSD best / quadtri TBB | MeshNormals serial / TBB ms | quadtri Vulkan ms | quadtri / OSD peak MiB |",
            "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for c in r["limit_cases"]:
        q, o = c["quadtri"], c["osd"]
        if o:
            osd_cols = (f"{timing(o['eval_cpu_ms'])} | {timing(o['eval_omp_ms'])} | {timing(o['eval_far_ms'])} | "
                        f"{ratio(osd_limit_best(o, True), limit_best(q, False))} | "
                        f"{ratio(osd_limit_best(o, False), limit_best(q, True))}")
        else:
            osd_cols = "– | – | – | – | –"
        rows.append(f"| {case_label(c)} | {c['points']} | {mib(q['table_bytes'])} / {mib(o['table_bytes']) if o else '–'} | "
                    f"{timing(q['limit_serial_ms'])} / {timing(q['levels_then_limit_serial_ms'])} | "
                    f"{timing(q['limit_threaded_ms'])} / {timing(q['levels_then_limit_threaded_ms'])} | {osd_cols} | "
                    f"{fmt(q['mesh_normals_serial_ms']['median'])} / {fmt(q['mesh_normals_threaded_ms']['median'])} | "
                    f"{timing(q['limit_vulkan_ms'])} | "
                    f"{mib(q['memory']['peak_resident_bytes'])} / {mib(o['memory']['peak_resident_bytes']) if o else '–'} |")
    return rows


def per_point(ms, points):
    return f"{1000.0 * ms / points:.3f}" if ms is not None else "–"


def error(v):
    return "–" if v is None else f"{v:.1e}"


def surface_table(r):
    rows = ["| mesh | scheme | points | way | factory ms | µs a point, new factory | µs a point, caches full"
            " | position error | normal error rad | OSD / quadtri: factory | points | caches full |",
            "|---|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for c in r.get("surface_cases", []):
        q = c["ways"][0]
        for w in c["ways"]:
            peer = w is not q
            warm = w["warm_ms"]["median"] if w["warm_ms"] else None
            q_warm = q["warm_ms"]["median"] if q["warm_ms"] else None
            rows.append(
                f"| {c['mesh']} | {c['scheme']} | {c['points']} | {w['library']} `{w['way']}` | "
                f"{timing(w['factory_ms'])} | {per_point(w['points_ms']['median'], c['points'])} | "
                f"{per_point(warm, c['points'])} | {error(w['position_error'])} | {error(w['normal_error'])} | "
                f"{ratio(median(w['factory_ms']), median(q['factory_ms'])) if peer else ''} | "
                f"{ratio(median(w['points_ms']), median(q['points_ms'])) if peer else ''} | "
                f"{ratio(warm, q_warm) if peer and warm and q_warm else ''} |")
    return rows


def tessellation_table(r):
    rows = ["| mesh | scheme | rate | way | points | triangles | first ms | frame ms | OSD / quadtri: first | frame |",
            "|---|---|---:|---|---:|---:|---:|---:|---:|---:|"]
    for c in r.get("tessellation_cases", []):
        q = c["ways"][0]
        for w in c["ways"]:
            peer = w is not q
            rows.append(
                f"| {c['mesh']} | {c['scheme']} | {c['rate']} | {w['library']} `{w['way']}` | {w['points']} | "
                f"{w['triangles']} | {timing(w['first_ms'])} | {timing(w['frame_ms'])} | "
                f"{ratio(median(w['first_ms']), median(q['first_ms'])) if peer else ''} | "
                f"{ratio(median(w['frame_ms']), median(q['frame_ms'])) if peer else ''} |")
    return rows


def edit_table(r):
    rows = ["| mesh | scheme | L | edit | points | stencils written | update ms | rebuild ms | rebuild / update |"
            " max difference | OSD rebuild ms | OSD / update |",
            "|---|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for c in r.get("edit_cases", []):
        osd = c.get("osd_rebuild_ms")
        rows.append(
            f"| {c['mesh']} | {c['scheme']} | {c['level']} | {c['edit'].replace('_', ' ')} | {c['points']} | "
            f"{c['stencils_written']} | {timing(c['update_ms'])} | {timing(c['rebuild_ms'])} | "
            f"{ratio(median(c['rebuild_ms']), median(c['update_ms']))} | {c['max_difference']:.1e} | "
            f"{timing(osd) + ' (' + c['osd_scheme'] + ')' if osd else '–'} | "
            f"{ratio(median(osd), median(c['update_ms'])) if osd else '–'} |")
    return rows


def summary(r):
    """Ratio ranges at levels >= 3 (all levels where no case reaches 3)."""
    osd_cases = [c for c in r["cases"] if c["osd"]]
    deep = [c for c in osd_cases if c["level"] >= 3] or osd_cases
    where = "levels >= 3" if any(c["level"] >= 3 for c in osd_cases) else "every level run"
    if not deep:
        return []
    n = r["threads"]

    def q(c, key):
        return c["quadtri"][key]["median"]

    serial = span([osd_best(c["osd"], SERIAL)[1] / q(c, "eval_serial_ms") for c in deep])
    serial4 = span([osd_best(c["osd"], SERIAL, 4)[1] / q(c, "eval_serial_4f_ms") for c in deep])
    serial3 = span([osd_best(c["osd"], SERIAL, 3)[1] / q(c, "eval_serial_ms") for c in deep])
    serial_ways = sorted({way_name(osd_best(c["osd"], SERIAL)[0]) for c in deep})
    threaded = span([osd_best(c["osd"])[1] / q(c, "eval_threaded_ms") for c in deep])
    threaded4 = span([osd_best(c["osd"])[1] / q(c, "eval_threaded_4f_ms") for c in deep])
    build1 = span([min(c["osd"]["build_per_level_ms"]["median"], c["osd"]["build_factorized_ms"]["median"])
                   / q(c, "build_1t_ms") for c in deep])
    build = span([min(c["osd"]["build_per_level_ms"]["median"], c["osd"]["build_factorized_ms"]["median"])
                  / q(c, "build_ms") for c in deep])
    fact = [c for c in deep if c["quadtri"].get("build_factorized_1t_ms")]
    fact1 = span([c["osd"]["build_factorized_ms"]["median"] / q(c, "build_factorized_1t_ms") for c in fact])
    fact_own = span([q(c, "build_factorized_1t_ms") / q(c, "build_1t_ms") for c in fact])
    pad = span([osd_best(c["osd"], ["cpu"], 3)[1] / osd_best(c["osd"], ["cpu"], 4)[1] for c in deep])
    omp = span([osd_best(c["osd"], ["omp"], w)[1] / osd_best(c["osd"], ["cpu"], w)[1] for c in deep for w in (3, 4)])
    bandwidth = span([gbps(c["quadtri"]["compulsory_bytes"], q(c, "eval_threaded_ms")) / r["memcpy"]["gbps_all"]
                      for c in deep])
    bandwidth1 = span([gbps(c["quadtri"]["compulsory_bytes"], q(c, "eval_serial_ms")) / r["memcpy"]["gbps_1t"]
                       for c in deep])
    osd_best_ways = sorted({way_name(osd_best(c["osd"])[0]) for c in deep})
    return [
        f"Ratios at {where} (OpenSubdiv / quadtri, medians):",
        f"- Evaluation, serial: {serial}x OpenSubdiv's best serial way ({'; '.join(serial_ways)}; quadtri 3 floats);"
        f" like width, both padded to 4 floats: {serial4}x; both at 3 floats: {serial3}x. Padding makes its"
        f" `CpuEvaluator` {pad}x faster (its SIMD path). quadtri's serial evaluation moves its compulsory bytes at {bandwidth1} of"
        f" the 1-thread 256 MiB memcpy bandwidth.",
        f"- Evaluation, {n} threads: `TbbEvaluator` {threaded}x OpenSubdiv's best way on any evaluator"
        f" ({'; '.join(osd_best_ways)}); at 4 floats {threaded4}x. Its `OmpEvaluator` (no SIMD path) takes {omp}x"
        f" the time of its `CpuEvaluator` at the same width. quadtri's threaded"
        f" evaluation moves its compulsory bytes at {bandwidth} of the {n}-thread 256 MiB memcpy bandwidth.",
        f"- Build (topology and tables): {build1}x OpenSubdiv's faster table kind with quadtri on 1 thread,"
        f" {build}x with quadtri on {n} threads (OpenSubdiv's factory is serial).",
        f"- Factorized build (topology and the last level's table over the control vertices): {fact1}x"
        f" OpenSubdiv's factorized `StencilTableFactory` with quadtri on 1 thread; quadtri's factorized build takes"
        f" {fact_own}x its per-level build.",
    ]


def limit_summary(r):
    cases = [c for c in r["limit_cases"] if c["osd"]]
    if not cases:
        return []
    n = r["threads"]
    serial = span([osd_limit_best(c["osd"], True) / limit_best(c["quadtri"], False) for c in cases])
    threaded = span([osd_limit_best(c["osd"], False) / limit_best(c["quadtri"], True) for c in cases])
    far = span([c["osd"]["eval_far_ms"]["median"] / c["osd"]["eval_cpu_ms"]["median"] for c in cases])
    omp = span([c["osd"]["eval_omp_ms"]["median"] / c["osd"]["eval_cpu_ms"]["median"] for c in cases])
    tables = span([c["quadtri"]["table_bytes"] / c["osd"]["table_bytes"] for c in cases if c["quadtri"]["table_bytes"]])
    return [f"Limit positions + normals: serial {serial}x OpenSubdiv's best serial way, {n} threads {threaded}x its"
            f" best on any evaluator (with derivatives its `OmpEvaluator` takes {omp}x the time of its `CpuEvaluator`,"
            f" Far's `UpdateValues` + `UpdateDerivs` {far}x);"
            f" quadtri's factorized limit tables are {tables}x the bytes of OpenSubdiv's `LimitStencilTable`."]


MESH_NORMALS = "levels_then_mesh_normals"
ROUTES = {"factorized_limit": "factorized limit", "levels_then_limit": "per-level + limit", "patches": "patches",
          "levels_then_mesh_normals": "per-level + mesh normals", "limit_stencils": "LimitStencilTable"}
OSD_EVALUATORS = {"cpu": "CpuEvaluator", "omp": "OmpEvaluator", "far": "Far UpdateValues + UpdateDerivs"}


def fastest_frame(timings, evaluators, mesh_normals=False):
    """The fastest of the frames run on one of `evaluators`: limit frames, or the mesh-normal frame."""
    ways = [t for t in timings or [] if t["evaluator"] in evaluators and (t["route"] == MESH_NORMALS) == mesh_normals]
    return min(ways, key=lambda t: t["frame_ms"]["median"]) if ways else None


def osd_frame(c, evaluator):
    """OpenSubdiv's frame like for like: serial against its serial ways, the rest against any."""
    return fastest_frame(c["osd"], SERIAL if evaluator == "cpu" else ("cpu", "omp", "far"))


def fps(t):
    """frames per second of the median frame, and over the fastest and slowest frames."""
    f = t["frame_ms"]
    return f"{1000 / f['median']:.0f} ({1000 / f['max']:.0f}–{1000 / f['min']:.0f})"


def frame_table(r):
    rows = ["| cage | scheme | L | faces | points | evaluator | quadtri frame ms (route) | quadtri fps"
            " | deform / evaluate / normals ms | OSD frame ms (evaluator) | OSD fps | OSD / quadtri"
            " | quadtri mesh-normal frame ms | fps |",
            "|---|---|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for c in r.get("frame_cases", []):
        for evaluator in ("cpu", "tbb", "vulkan"):
            q = fastest_frame(c["quadtri"], (evaluator,))
            if not q:
                continue
            o = osd_frame(c, evaluator)
            osd_cols = (f"{timing(o['frame_ms'])} ({OSD_EVALUATORS[o['evaluator']]}) | {fps(o)} | "
                        f"{ratio(o['frame_ms']['median'], q['frame_ms']['median'])}") if o else "– | – | –"
            m = fastest_frame(c["quadtri"], (evaluator,), mesh_normals=True)
            mesh_cols = f"{timing(m['frame_ms'])} | {fps(m)}" if m else "– | –"
            phases = " / ".join(fmt(q[k]["median"]) for k in ("deform_ms", "evaluate_ms", "normals_ms"))
            name = {"cpu": "CpuEvaluator", "tbb": f"TbbEvaluator, {r['threads']}t", "vulkan": "Vulkan"}[evaluator]
            rows.append(f"| {case_label(c)} | {c['faces']} | {c['points']} | {name} | {timing(q['frame_ms'])}"
                        f" ({ROUTES[q['route']]}) | {fps(q)} | {phases} | {osd_cols} | {mesh_cols} |")
    return rows


def frame_summary(r):
    """The headline: the issue's goal (the mixed cage at level 3 on all threads, >= 4x OpenSubdiv's
    frame on the pure cages) and the ratio ranges."""
    cases = r.get("frame_cases", [])
    if not cases:
        return []
    n = r["threads"]
    lines = ["**The whole frame** (the headline: what an engine pays per frame for a skinned, subdivided cage).",
             ""]
    mixed = [c for c in cases if not c["osd"]]
    pure = [c for c in cases if c["osd"]]
    goal_level = 3 if any(c["level"] == 3 for c in cases) else max(c["level"] for c in cases)
    for c in (c for c in mixed if c["level"] == goal_level):
        t = fastest_frame(c["quadtri"], ("tbb",))
        lines.append(f"- Goal, a 10 000-face mixed cage at level 3 with limit normals at >= 120 fps on 2 cores with"
                     f" oneTBB: {c['mesh']} ({c['faces']} faces) at level {c['level']} on {n} threads,"
                     f" {timing(t['frame_ms'])} ms a frame, **{fps(t)} fps** ({ROUTES[t['route']]});"
                     f" one thread {fps(fastest_frame(c['quadtri'], ('cpu',)))} fps.")
    at = [c for c in pure if c["level"] == goal_level]
    if at:
        serial = span([osd_frame(c, "cpu")["frame_ms"]["median"] / fastest_frame(c["quadtri"], ("cpu",))["frame_ms"]["median"]
                       for c in at])
        threaded = span([osd_frame(c, "tbb")["frame_ms"]["median"] / fastest_frame(c["quadtri"], ("tbb",))["frame_ms"]["median"]
                         for c in at])
        names = ", ".join(sorted({c["mesh"] for c in at}))
        lines.append(f"- Goal, >= 4x OpenSubdiv's frame: OpenSubdiv has no scheme for mixed cages, so the ratio is on"
                     f" the pure cages ({names}: Catmark and Loop on both sides) at level {goal_level}:"
                     f" **{threaded}x** its best frame on any evaluator with quadtri on {n} threads,"
                     f" {serial}x its best serial frame with quadtri on one thread.")
    if pure:
        serial = span([osd_frame(c, "cpu")["frame_ms"]["median"] / fastest_frame(c["quadtri"], ("cpu",))["frame_ms"]["median"]
                       for c in pure])
        threaded = span([osd_frame(c, "tbb")["frame_ms"]["median"] / fastest_frame(c["quadtri"], ("tbb",))["frame_ms"]["median"]
                         for c in pure])
        lines.append(f"- Every level run ({', '.join(str(l) for l in sorted({c['level'] for c in pure}))}): serial"
                     f" {serial}x, {n} threads {threaded}x OpenSubdiv's frame.")
    lines += ["", "Frames per second are 1000 / the median frame (in brackets: of the slowest and the fastest frame);"
              " each evaluator's faster route of the two limit routes; OpenSubdiv's fastest evaluator like for like"
              " (one thread: `Osd::CpuEvaluator` or Far's templates; threads and Vulkan: any, `Osd::OmpEvaluator`"
              " included); the phases' normals are 0 where the route's evaluation pass gives the normals too (a"
              " limit table's positions and tangents in one pass); the mesh-normal frame (quadtri alone) evaluates"
              " the per-level tables to level N and its mesh normals:", ""]
    return lines + frame_table(r)


def section(r, note):
    m = r["memcpy"]
    lines = [
        BEGIN,
        "",
        f"Measured {r['date']} with `{r['command']}` on {r['cpu']}, {r['threads']} threads (oneTBB's concurrency;"
        f" OpenSubdiv's OpenMP set to the same){'; ' + note if note else ''}. Each time is the median of"
        f" {r['repetitions']} repetitions after a warm-up, the run's fastest and slowest in brackets; written by"
        f" `{COMMAND}`.",
        "",
        f"memcpy in the same run (bytes read + written): 256 MiB {m['gbps_1t']:.1f} GB/s on 1 thread,"
        f" {m['gbps_all']:.1f} GB/s on {r['threads']}.",
        "",
    ]
    lines += frame_summary(r)
    if r.get("frame_cases"):
        lines += [""]
    lines += summary(r)
    if not r["cases"]:  # a --limit or --frame run
        lines += ["No refinement cases in this run."]
    else:
        lines += case_tables(r)
    if r["limit_cases"]:
        lines += ["", "Limit positions + unit normals per frame (3 floats; the chain: per-level tables, then the"
                  " limit table over the last level; OpenSubdiv: its `LimitStencilTable` through `Osd::CpuEvaluator`,"
                  " `Osd::OmpEvaluator`, or Far's `UpdateValues` + `UpdateDerivs` compiled into the bench):", ""]
        lines += limit_table(r)
        lines += [""] + limit_summary(r)
    if r.get("surface_cases"):
        lines += ["", "Surface evaluation at random (u, v), 8 a face (1 with `--quick`), grouped by face, serial, 3 floats:"
                  " position, du, dv, then the unit normal (quadtri: `FaceSurfaceFactory` + `FaceSurface::evaluate` of a face's points as one batch;"
                  " OpenSubdiv: `Bfr::Surface` at its default approximation levels 2 smooth / 6 sharp and at 10, and"
                  " `Far::PatchTable` adaptive to level 2 with Gregory end caps, `Far::PatchMap` and"
                  " `Osd::CpuEvaluator::EvalPatches`, its local points by a stencil table each time). Factory: from the"
                  " mesh's arrays (refiner, analysis, patch table). A new factory's pass grows its caches (quadtri's"
                  " trees, Bfr's irregular patches; the patch table finds each point's patch); caches full: the same"
                  " points again. Errors: against Bfr at level 10 evaluated in double, of the bounding-box diagonal:", ""]
        lines += surface_table(r)
    if r.get("tessellation_cases"):
        lines += ["", "Tessellation of every face at a uniform rate (4; 2 with `--quick`), serial, 3 floats: points, unit"
                  " normals and triangles (quadtri: `Tessellation`, each shared edge's and vertex's points once, their"
                  " stencils as one `LimitSurface::stencilTable`, `CpuEvaluator::EvalLimitStencils` each frame, the"
                  " table built on one thread; OpenSubdiv: per face `Bfr::Surface` at its defaults,"
                  " `Bfr::Tessellation` and `Surface::Evaluate` at each coordinate, each face its own edge points)."
                  " First: from the mesh's arrays to the first draw-ready buffers; frame: the cage moved, the same"
                  " triangles' points and normals again (Bfr keeps each face's `Surface`). The two tessellations'"
                  " areas are checked to agree within 1e-3 first:", ""]
        lines += tessellation_table(r)
    if r.get("edit_cases"):
        lines += ["", "Edits in place ([edits.md](edits.md)): one edit of the cage's tags (an interior edge to"
                  " sharpness 2.5, ten edges along a quad loop, an interior vertex's corner, a face made a hole)"
                  " through `Refiner::applyEdits` and `LimitTableUpdate` of the frame's factorized limit table, all"
                  " threads, each repetition from the unedited cage; rebuild: the `Refiner`, `refineUniform(N)` and"
                  " `factorizedLimitStencils(N)` built again from the edited cage; max difference: the farthest limit"
                  " point of the updated table from the rebuilt one's, of the bounding-box diagonal. OpenSubdiv has no"
                  " edit in place: its rebuild (serial, under Catmark, the scheme it has for these cages) is a"
                  " `TopologyRefiner` with `RefineUniform(N)` and a factorized `StencilTable`, and one refined"
                  " adaptively (isolation 2) with its `LimitStencilTable` at the level's points:", ""]
        lines += edit_table(r)
    lines += ["", END]
    return "\n".join(lines) + "\n"


def case_tables(r):
    vulkan = r.get("vulkan_device")
    lines = ["", "Evaluation on one thread (quadtri `CpuEvaluator`; OpenSubdiv's fastest serial way at each width,"
              " named: `Osd::CpuEvaluator` or `Far::StencilTable::UpdateValues` on its per-level or factorized table;"
              " 3f / 4f: floats a vertex; last column: quadtri's"
              " compulsory bytes per second over 1-thread memcpy of a copy the size of the working set, and of"
              " 256 MiB):", ""]
    lines += serial_table(r)
    lines += ["", f"Evaluation on {r['threads']} threads (quadtri `TbbEvaluator`; OpenSubdiv's fastest of every"
              " table, evaluator and width, named):", ""]
    lines += threaded_table(r)
    lines += ["", "Build, topology and tables included (quadtri: `Refiner` + `refineUniform`, oneTBB limited by"
              " `tbb::global_control` for 1t; OpenSubdiv: `TopologyRefiner` + `RefineUniform` + `StencilTableFactory`):", ""]
    lines += build_table(r)
    lines += ["", "Factorized build, topology and the last level's table over the control vertices (quadtri:"
              " `refineUniform` without per-level tables, `LevelTables::None`, and `factorizedStencils(L)`;"
              " OpenSubdiv: its factory with `factorizeIntermediateLevels`, serial, no intermediate levels kept);"
              " last column: quadtri's factorized build over its per-level build, both on 1 thread:", ""]
    lines += factorized_build_table(r)
    lines += ["", "Memory: tables by count; peak is the most memory resident above what was resident when the"
              " case's untimed first run began (build with its transient arrays, tables, the 3-float level buffers;"
              " OpenSubdiv's per-level table with its refiner):", ""]
    lines += memory_table(r)
    vt = vulkan_table(r)
    if vt:
        lines += ["", f"Vulkan on {vulkan}:", ""] + vt
    else:
        lines += ["", "No Vulkan figures in this run."]
    return lines


def headline(r, note):
    """README's table: a few rows, each one figure of the run (none where the run lacks it)."""
    n = r["threads"]
    rows = []
    frames = r.get("frame_cases", [])
    if frames:
        goal_level = 3 if any(c["level"] == 3 for c in frames) else max(c["level"] for c in frames)
        for c in (c for c in frames if not c["osd"] and c["level"] == goal_level):
            tbb, cpu = fastest_frame(c["quadtri"], ("tbb",)), fastest_frame(c["quadtri"], ("cpu",))
            what = (f"Whole frame: `{c['mesh']}` ({c['faces']} faces, {c['scheme']}) skinned, level {c['level']}'s"
                    f" {c['points']} limit points and normals")
            if tbb:
                rows.append(f"| {what}, oneTBB on {n} threads | **{fps(tbb)} fps** ({fmt(tbb['frame_ms']['median'])} ms) |"
                            " quadtri alone (OpenSubdiv has no mixed scheme) |")
            if cpu:
                rows.append(f"| the same frame on one thread | {fps(cpu)} fps ({fmt(cpu['frame_ms']['median'])} ms) | |")
        at = [c for c in frames if c["osd"] and c["level"] == goal_level]
        if at:
            names = ", ".join(f"`{m}`" for m in sorted({c["mesh"] for c in at}))

            def frame_ratio(c, evaluator):
                return osd_frame(c, evaluator)["frame_ms"]["median"] / fastest_frame(c["quadtri"], (evaluator,))["frame_ms"]["median"]

            rows.append(f"| Whole frame on the pure cages ({names}), level {goal_level}, quadtri on {n} threads |"
                        f" **{span([frame_ratio(c, 'tbb') for c in at])}x** | OpenSubdiv's best frame on any evaluator |")
            rows.append(f"| the same, quadtri on one thread | {span([frame_ratio(c, 'cpu') for c in at])}x |"
                        " OpenSubdiv's best serial frame |")
    osd_cases = [c for c in r["cases"] if c["osd"]]
    deep = [c for c in osd_cases if c["level"] >= 3] or osd_cases
    if deep:
        where = "levels >= 3" if any(c["level"] >= 3 for c in osd_cases) else "every level run"
        tori = ", ".join(f"`{m}`" for m in sorted({c["mesh"] for c in deep}))
        rows.append(f"| Stencil evaluation, one thread ({tori}, {where}) |"
                    f" {span([osd_best(c['osd'], SERIAL)[1] / c['quadtri']['eval_serial_ms']['median'] for c in deep])}x |"
                    " OpenSubdiv's best serial way |")
        rows.append(f"| Stencil evaluation, {n} threads (the same cases) |"
                    f" {span([osd_best(c['osd'])[1] / c['quadtri']['eval_threaded_ms']['median'] for c in deep])}x |"
                    " OpenSubdiv's best way on any evaluator |")
        fact = [c for c in deep if c["quadtri"].get("build_factorized_1t_ms")]
        if fact:
            rows.append("| Factorized table build, topology included, one thread (the same cases) |"
                        f" {span([c['osd']['build_factorized_ms']['median'] / c['quadtri']['build_factorized_1t_ms']['median'] for c in fact])}x |"
                        " OpenSubdiv's `StencilTableFactory` |")
        rows.append("| Per-level table bytes (the same cases) |"
                    f" {span([c['quadtri']['table_bytes'] / c['osd']['table_bytes'] for c in deep])}x |"
                    " OpenSubdiv's per-level tables (lower is better) |")
    lines = [HEADLINE_BEGIN, ""]
    if rows:
        lines += ["| measured | quadtri | against (ratios: OpenSubdiv's time / quadtri's) |", "|---|---:|---|"] + rows
    else:
        lines += ["No frame or refinement cases in this run."]
    lines += ["", f"Measured {r['date']} with `{r['command']}` on {r['cpu']}, {n} threads"
              f"{'; ' + note if note else ''}; medians of {r['repetitions']} repetitions. Every figure, and how it"
              f" is measured: [docs/performance.md](docs/performance.md). Written by `{COMMAND}`.", "", HEADLINE_END]
    return "\n".join(lines) + "\n"


def replace_between(path, begin_marker, end_marker, text):
    """Writes `text` (which holds both markers) over the span between the markers in `path`;
    returns False, saying why on stderr, when the file lacks them."""
    with open(path) as f:
        old = f.read()
    begin, end = old.find(begin_marker), old.find(end_marker)
    if begin < 0 or end < begin:
        print(f"performance_section.py: {path} lacks the marker lines {begin_marker!r} ... {end_marker!r}",
              file=sys.stderr)
        return False
    rest = old[end + len(end_marker):]
    new = old[:begin] + text + (rest[1:] if rest.startswith("\n") else rest)
    if new != old:
        with open(path, "w") as f:
            f.write(new)
    return True


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("json", help="quadtri-bench --json output")
    parser.add_argument("--readme", default="README.md", help="the file that gets the headline table (default README.md)")
    parser.add_argument("--doc", default="docs/performance.md",
                        help="the file that gets every figure (default docs/performance.md)")
    parser.add_argument("--note", default="", help="a few words on the machine's state, written after the threads")
    args = parser.parse_args()
    with open(args.json) as f:
        result = json.load(f)
    # Both files are checked for their markers before either is written.
    for path, markers in ((args.doc, (BEGIN, END)), (args.readme, (HEADLINE_BEGIN, HEADLINE_END))):
        with open(path) as f:
            text = f.read()
        if text.find(markers[0]) < 0 or text.find(markers[1]) < text.find(markers[0]):
            print(f"performance_section.py: {path} lacks the marker lines {markers[0]!r} ... {markers[1]!r}",
                  file=sys.stderr)
            return 2
    ok = replace_between(args.doc, BEGIN, END, section(result, args.note))
    ok = replace_between(args.readme, HEADLINE_BEGIN, HEADLINE_END, headline(result, args.note)) and ok
    return 0 if ok else 2


if __name__ == "__main__":
    sys.exit(main())
