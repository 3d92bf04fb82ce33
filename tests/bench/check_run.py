#!/usr/bin/env python3
"""check_run.py RUN_JSON [--loss-cell ID --loss PERCENT] [--delay-ms D] [--baseline-flags ID]

Checks a `plexus bench` run.json (docs/qos-bench.md) the way a user's CI would read it:
  * every cell of the matrix is present (pairs x transports x profiles x sizes x topologies),
    each ok one with every measure: per rate a one-way and a round-trip distribution with
    samples (p50 <= p99 <= p999 <= max), sent/received/lost/late; throughput; CPU of both ends;
    the clock offset; spreads; on one host for a same-vendor pair, the vendor's tool and the
    ratio to it;
  * --loss-cell ID --loss P: that cell's one-way loss at the headline rate is the link's P %
    within four binomial standard deviations (best effort: a lost packet is a lost sample);
  * --delay-ms D: every ok two_ns cell's one-way p50 at the headline rate is D ms plus at
    most 3 ms, its round-trip p50 at least 2 D (the relay delays each way);
  * --baseline-flags ID: the run's baseline comparison found regressions, all of them in ID.
Prints one line per failure; exits 1 on any.
"""
import json
import math
import sys


def main():
    args = sys.argv[1:]
    run = json.load(open(args[0]))
    opts = dict(zip(args[1::2], args[2::2]))
    failures = []
    fail = failures.append
    m = run["matrix"]
    expected = (len(m["pairs"]) * len(m["transports"]) * len(m["profiles"]) * len(m["sizes"])
                * len(m["topologies"]))
    cells = run["cells"]
    if len(cells) != expected:
        fail(f"{len(cells)} cells, the matrix has {expected}")
    if len({c["id"] for c in cells}) != len(cells):
        fail("a cell id is listed twice")
    headline = next((r for r in m["rates_hz"] if r > 0), 0)
    for c in cells:
        cid = c["id"]
        if c["status"] == "not_applicable":
            if not c.get("reason"):
                fail(f"{cid}: not_applicable without a reason")
            continue
        if c["status"] != "ok":
            fail(f"{cid}: {c['status']}: {c.get('reason')}")
            continue
        rates = [e["rate_hz"] for e in c["latency"]]
        if rates != m["rates_hz"]:
            fail(f"{cid}: latency rates {rates}, the matrix has {m['rates_hz']}")
        for e in c["latency"]:
            for key in ("one_way_us", "round_trip_us"):
                d = e[key]
                if d["count"] <= 0:
                    fail(f"{cid} @ {e['rate_hz']} Hz: no {key} samples")
                    continue
                if not d["p50"] <= d["p99"] <= d["p999"] <= d["max"]:
                    fail(f"{cid} @ {e['rate_hz']} Hz: {key} percentiles out of order")
                if not d["cdf"]:
                    fail(f"{cid} @ {e['rate_hz']} Hz: {key} has no CDF")
            for key in ("sent", "received", "lost", "late"):
                if not isinstance(e.get(key), int) or e[key] < 0:
                    fail(f"{cid} @ {e['rate_hz']} Hz: {key} missing or negative")
            if e["sent"] <= 0 or e["received"] > e["sent"]:
                fail(f"{cid} @ {e['rate_hz']} Hz: sent {e['sent']}, received {e['received']}")
        t = c.get("throughput")
        if m["throughput_seconds"] > 0 and (not t or t["samples_per_s"] <= 0 or t["mb_per_s"] <= 0):
            fail(f"{cid}: no throughput")
        cpu = c.get("cpu_percent") or {}
        if not (cpu.get("writer", 0) > 0 and cpu.get("reader", 0) > 0):
            fail(f"{cid}: no CPU figure for both ends")
        for key in ("clock_offset_us", "spread", "recovery", "events"):
            if key not in c:
                fail(f"{cid}: no {key}")
        if c["topology"] == "two_ns" and c["size"] == m["sizes"][0] and not c.get("recovery"):
            fail(f"{cid}: no recovery figure across the namespaces")
        # The QoS events, where the profile sets them (on the group's first size): the time from
        # the writer's last sample to the event, between the period and a loose upper bound.
        for event, limit in (("deadline", "period_s"), ("liveliness", "lease_s")):
            e = (c.get("events") or {}).get(event)
            if not e:
                continue
            after, bound = e.get("detected_after_s"), e[limit]
            if after is None:
                fail(f"{cid}: no {event} event within its wait")
            elif not 0.9 * bound <= after <= 2 * bound + 1.0:
                fail(f"{cid}: {event} detected after {after:.3f} s, {limit} {bound} s")
        same = c["writer_dds"] == c["reader_dds"]
        if m["vendor_tools"] and same and c["topology"] == "one_host":
            v = c.get("vendor_tool") or {}
            if not v.get("round_trip_us"):
                fail(f"{cid}: no vendor tool round trip")
            if not (c.get("ratio") or {}).get("round_trip_p50"):
                fail(f"{cid}: no ratio to the vendor tool")
    if "--loss-cell" in opts:
        cid, p = opts["--loss-cell"], float(opts["--loss"]) / 100
        c = next((c for c in cells if c["id"] == cid), None)
        e = c and next((e for e in c["latency"] if e["rate_hz"] == headline), None)
        if not e:
            fail(f"{cid}: not in the run")
        else:
            n, lost = e["sent"], e["lost"]
            sd = math.sqrt(n * p * (1 - p))
            lo, hi = n * p - 4 * sd, n * p + 4 * sd
            print(f"{cid}: lost {lost} of {n} ({100 * lost / n:.1f} %), link loss {100 * p:g} %, "
                  f"expected {lo:.0f}..{hi:.0f}")
            if not lo <= lost <= hi:
                fail(f"{cid}: lost {lost} of {n}, outside {lo:.0f}..{hi:.0f} for {100 * p:g} % loss")
    if "--delay-ms" in opts:
        d_us = float(opts["--delay-ms"]) * 1000
        for c in cells:
            if c["status"] != "ok" or c["topology"] != "two_ns":
                continue
            e = next((e for e in c["latency"] if e["rate_hz"] == headline), None)
            ow, rt = e["one_way_us"]["p50"], e["round_trip_us"]["p50"]
            print(f"{c['id']}: one-way p50 {ow:.0f} us, round trip p50 {rt:.0f} us, link delay {d_us:.0f} us")
            if not d_us <= ow <= d_us + 3000:
                fail(f"{c['id']}: one-way p50 {ow:.0f} us, expected {d_us:.0f}..{d_us + 3000:.0f}")
            if rt < 2 * d_us:
                fail(f"{c['id']}: round trip p50 {rt:.0f} us, below twice the delay")
    if "--baseline-flags" in opts:
        want = opts["--baseline-flags"]
        regs = (run.get("baseline") or {}).get("regressions", [])
        flagged = sorted({r["cell"] for r in regs})
        print(f"baseline: regressions in {flagged}")
        if flagged != [want]:
            fail(f"baseline flagged {flagged}, expected exactly [{want}]")
    for f in failures:
        print("FAIL: " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
