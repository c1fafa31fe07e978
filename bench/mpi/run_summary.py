"""What an `isphdem run` printed and wrote, for the bench/mpi scripts: the particle count, steps,
PPE iterations, setup and iteration ms per step and the exchanges' ms per step from the summary,
the wall time, rows_shared and decomposed from result.json (the summary line rounds the wall
time), and the largest "maxrss_kb N" line /usr/bin/time wrote for a rank into LOG.rss (0
without one)."""
import json
import os
import re


def read(log, result_json):
    text = open(log).read()
    m = re.search(r"particles: (\d+) fluid, (\d+) wall", text) or \
        re.search(r"fluid: (\d+) fluid, (\d+) wall particles", text)
    setup, iterate = map(float, re.search(
        r"setup ([\d.e+]+) ms/step, iterations ([\d.e+]+) ms/step", text).groups())
    exchange = re.search(r"exchanges ([\d.e+-]+) ms/step", text)
    result = json.load(open(result_json))
    rss = open(log + ".rss").read() if os.path.exists(log + ".rss") else ""
    return {
        "particles": int(m[1]) + int(m[2]),
        "steps": int(re.search(r"in (\d+) (?:fluid )?steps", text)[1]),
        "ppe_it": float(re.search(r"([\d.]+) PPE iterations/step", text)[1]),
        "setup_ms": setup,
        "iterate_ms": iterate,
        "exchange_ms": float(exchange[1]) if exchange else 0.0,
        "wall_s": result["wall_seconds"],
        "rows_shared": bool(result.get("rows_shared")),
        "decomposed": bool(result.get("decomposed")),
        "max_rss_mb": max([int(k) for k in re.findall(r"maxrss_kb (\d+)", rss)] or [0]) / 1024,
    }
