#!/usr/bin/env python3
"""Hunting power on the fault zoo (scripts/bench-hunt.sh runs this; figures go in BENCHMARKS.md).

For each planner (the zoo planner with each of its planted faults, with three faults at once in a fixed sample of
twelve combinations, and MRPT's wavefront planner) and each route:
  shipped  config/planner_hunt.yaml as it is, with only its agent entry swapped for the planner's;
  today    the same file as it was at commit TODAY (the hunt before failure signatures), each hunt given as many
           matings as the shipped hunt of its name, so that both spend as many evaluations;
  random   random search: the route's reference sets, and in place of its hunts one set of as many random solvable
           PPPs (same generator options: size, obstacle budget) as the shipped route evaluated, each scored once;
it runs the experiment through roslaunch, then shrinks the hunted PPPs that failed into a corpus, and reports:
  broken      the hunted set fails >= 80 % of the planner's runs and >= 0.4 more than the reference `turns` set
              (random search's hunted set: the 20 PPPs it found failing most, as many as the hunt's set holds);
  evaluations the PPPs its hunts scored (evaluations.csv), and the evaluation and seconds of the first that failed;
  failing     distinct failing PPPs per 1,000 evaluations;
  traps       distinct minimal traps: the hunted set's failing PPPs shrunk, deduplicated up to translation, mirror
              and rotation (the corpus keeps one PPP per obstacle shape);
  signatures  distinct failure signatures of the planner's failed runs on the hunted set;
and for a planner with several faults:
  recall      the share of its faults the hunted set reveals: a PPP reveals fault f when the zoo planner with f alone
              fails it and the optimistic planner (no fault) passes it, decided by playing them on the hunted set
              (each PPP's verdicts in OUT/attribution.csv);
  first       per fault, the evaluation at which the first hunted PPP revealing it was scored.
The sample: 12 of the 50 plantable three-fault combinations (dead_end_filter never with goal_clearance), drawn
with SAMPLE_SEED until every fault is in at least three of them.
"""
import argparse
import collections
import csv
import glob
import itertools
import json
import os
import random
import shutil
import socket
import subprocess
import sys
import time

import yaml

ROOT = os.path.dirname(os.path.dirname(os.path.realpath(__file__)))
ZOO_FAULTS = ["search_horizon", "expansion_budget", "open_list_cap", "west_edge", "goal_clearance",
              "dead_end_filter", "no_backtrack", "replan_limit"]
SAMPLE_SEED = 72
ROUTES = ["shipped", "today", "random"]
TODAY = "488355d"  # config/planner_hunt.yaml before failure signatures
AGENT = "mine"
REFERENCE_SET = "turns"


def fault_sample():
    """The fixed sample of three-fault planners, "a+b+c" each."""
    combos = [c for c in itertools.combinations(ZOO_FAULTS, 3)
              if not {"dead_end_filter", "goal_clearance"} <= set(c)]
    rng = random.Random(SAMPLE_SEED)
    while True:
        sample = rng.sample(combos, 12)
        counts = collections.Counter(f for c in sample for f in c)
        if all(counts[f] >= 3 for f in ZOO_FAULTS):
            return ["+".join(c) for c in sample]


PLANNERS = ZOO_FAULTS + fault_sample() + ["mrpt"]


def faults_of(planner):
    return planner.split("+") if planner != "mrpt" else []


def agent_entry(planner, name=AGENT):
    """The agent entry that puts `planner` ("none": the optimistic planner without a fault) in the config's place
    for the user's planner."""
    if planner == "mrpt":  # as config/planner_hunt.yaml's comments give it
        return {"name": name, "type": "planner", "planner_node": "ppp_agents/mrpt_planner_node",
                "cells_per_ppp_cell": 4, "planner_args": "_inflation:=1"}
    if planner == "none":
        return {"name": name, "type": "planner", "planner_node": "ppp_agents/optimistic_planner_node"}
    return {"name": name, "type": "planner", "planner_node": "ppp_agents/zoo_planner_node",
            "planner_args": "_fault:=" + ",".join(faults_of(planner))}


def is_hunt(entry):
    return (entry.get("generator") or {}).get("fitness") in ("failure", "regret")


def route_config(route, planner, evaluations, shipped):
    """The experiment config of a route for a planner (`evaluations`: the random search's budget; `shipped`: the
    hunt config's path)."""
    if route == "today":
        text = subprocess.run(["git", "-C", ROOT, "show", TODAY + ":config/planner_hunt.yaml"], check=True,
                              capture_output=True, text=True).stdout
    else:
        with open(shipped) as f:
            text = f.read()
    config = yaml.safe_load(text)
    config["agents"] = [agent_entry(planner) if a["name"] == AGENT else a for a in config["agents"]]
    if route == "today":  # at the shipped hunts' number of matings, so that both spend as many evaluations
        with open(shipped) as f:
            matings = {s["name"]: s["generator"].get("matings", 10000) for s in yaml.safe_load(f)["sets"] if is_hunt(s)}
        for s in config["sets"]:
            if s["name"] in matings and is_hunt(s):
                s["generator"]["matings"] = matings[s["name"]]
    if route == "random":
        hunt = next(s for s in config["sets"] if is_hunt(s) and s["generator"]["fitness"] == "failure")["generator"]
        search = {k: v for k, v in hunt.items() if k not in ("initial_pool", "crowding_window", "matings")}
        search.update({"runs_per_eval": 1, "population": evaluations, "matings": 0})
        config["sets"] = [s for s in config["sets"] if not is_hunt(s)] + [{"name": "random_" + AGENT,
                                                                           "generator": search}]
    return config


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def roslaunch(launch_file, arguments, log):
    """Runs a launch file on a fresh loopback master; returns the wall seconds."""
    port = free_port()
    env = dict(os.environ, ROS_MASTER_URI="http://127.0.0.1:%d" % port, ROS_IP="127.0.0.1")
    start = time.monotonic()
    with open(log, "w") as out:
        subprocess.run([os.path.join(ROOT, "scripts", "loopback-only"), "roslaunch", "-p", str(port),
                        os.path.join(ROOT, "launch", launch_file)] + arguments, env=env, stdout=out,
                       stderr=subprocess.STDOUT, check=True)
    return time.monotonic() - start


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def evaluation_log(out):
    """Every evaluation of the route's hunts, in the order of their seconds (hunts run side by side)."""
    rows = []
    for path in glob.glob(os.path.join(out, "sets", "*", "evaluations.csv")):
        rows += read_csv(path)
    rows.sort(key=lambda r: float(r["seconds"]))
    return rows


def failure_share(results, set_name, problems=None):
    runs = [r for r in results if r["agent"] == AGENT and r["set"] == set_name
            and (problems is None or r["problem"] in problems)]
    return sum(1 for r in runs if r["pass"] == "0") / len(runs) if runs else float("nan")


def measure(route, planner, out, seconds, config_path, size):
    """The figures of a finished route; `size`: the PPPs of the hunted set (random search: its `size` fittest)."""
    results = read_csv(os.path.join(out, "results.csv"))
    log = evaluation_log(out)
    first = next((i for i, r in enumerate(log) if float(r["failure_rate"]) > 0), None)
    failing_grids = {r["grid"] for r in log if float(r["failure_rate"]) > 0}
    hunted_set = "random_" + AGENT if route == "random" else "hunted_" + AGENT
    hunted_rows = read_csv(os.path.join(out, "sets", hunted_set, "set.csv"))[:size]  # fittest first
    hunted = [r["id"] for r in hunted_rows]
    hunted_failure = failure_share(results, hunted_set, set(hunted))
    reference_failure = failure_share(results, REFERENCE_SET)
    failing = [r for r in hunted_rows
               if any(x["set"] == hunted_set and x["problem"] == r["id"] and x["agent"] == AGENT and x["pass"] == "0"
                      for x in results)]
    traps = shrink_into_corpus(out, hunted_set, failing, config_path) if failing else 0
    signatures = {r["signature"] for r in results if r["set"] == hunted_set and r["problem"] in hunted
                  and r["agent"] == AGENT and r["signature"]}
    diagnoses = collections.Counter(r["diagnosis"] + (" endless" if r["endless_step"] else "") for r in results
                                    if r["set"] == hunted_set and r["problem"] in hunted and r["agent"] == AGENT
                                    and r["diagnosis"])
    attributed = attribute(out, planner, hunted_set, hunted_rows, config_path, log) if len(faults_of(planner)) > 1 \
        else {}
    hunt_seconds = max((float(r["seconds"]) for r in log), default=0.0)  # the hunts of a route run side by side
    steps = sum(int(r["steps"]) for r in log)
    return {"planner": planner, "route": route, "seconds": round(seconds, 1), "evaluations": len(log),
            "hunt_seconds": hunt_seconds, "steps_per_evaluation": round(steps / len(log), 1) if log else 0.0,
            "ms_per_evaluation": round(1000 * hunt_seconds / len(log), 3) if log else 0.0,
            "us_per_step": round(1e6 * hunt_seconds / steps, 2) if steps else 0.0,
            "first_failing_evaluation": first + 1 if first is not None else None,
            "first_failing_seconds": float(log[first]["seconds"]) if first is not None else None,
            "failing_per_1000": round(1000.0 * len(failing_grids) / len(log), 2) if log else 0.0,
            "hunted_failure": round(hunted_failure, 3), "reference_failure": round(reference_failure, 3),
            "broken": hunted_failure >= 0.8 and hunted_failure - reference_failure >= 0.4,
            "hunted_failing_ppps": len(failing), "traps": traps, "signatures": len(signatures),
            "diagnoses": dict(diagnoses), **attributed}


def grid_hash(ppp_path):
    """Grid::hash() of a .ppp file's grid: FNV-1a over its cells, row by row, 1 for an obstacle."""
    with open(ppp_path) as f:
        lines = f.read().split("\n")
    rows = lines[lines.index("grid") + 1:]
    h = 0xcbf29ce484222325
    for row in rows:
        if not row or row[0] not in ".#SG":
            break
        for c in row:
            h = ((h ^ (1 if c == "#" else 0)) * 0x100000001b3) % (1 << 64)
    return "%016x" % h


def attribute(out, planner, hunted_set, hunted_rows, config_path, log):
    """Plays the optimistic planner and each of the planner's faults alone on the hunted PPPs; the share of its
    faults some hunted PPP reveals, and per fault the evaluation of the first such PPP."""
    faults = faults_of(planner)
    directory = os.path.join(out, "attributed")
    os.makedirs(directory, exist_ok=True)
    for row in hunted_rows:
        shutil.copy(os.path.join(out, "sets", hunted_set, row["file"]), directory)
    with open(config_path) as f:
        config = yaml.safe_load(f)
    config["agents"] = [agent_entry("none", "none")] + [agent_entry(f, f) for f in faults]
    config["sets"] = [{"name": "attributed", "directory": directory}]
    attribution_config = os.path.join(out, "attribution.yaml")
    with open(attribution_config, "w") as f:
        yaml.safe_dump(config, f, sort_keys=False)
    played = os.path.join(out, "attribution")
    shutil.rmtree(played, ignore_errors=True)
    roslaunch("experiment.launch", ["output_dir:=" + played, "config:=" + attribution_config],
              os.path.join(out, "attribution.log"))
    failed = collections.defaultdict(set)  # agent -> PPP files it failed
    ids = {os.path.splitext(name)[0]: name for name in os.listdir(directory)}  # a plain directory's ids: file stems
    for r in read_csv(os.path.join(played, "results.csv")):
        if r["pass"] == "0":
            failed[r["agent"]].add(ids[r["problem"]])
    order = {}
    for i, r in enumerate(log):
        order.setdefault(r["grid"], i + 1)
    first = {}
    with open(os.path.join(out, "attribution.csv"), "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["problem", "none"] + faults + ["reveals", "evaluation"])
        for row in hunted_rows:
            name = row["file"]
            reveals = [fault for fault in faults if name in failed[fault] and name not in failed["none"]]
            evaluation = order.get(grid_hash(os.path.join(directory, name)))
            for fault in reveals:  # the earliest evaluation of a PPP revealing it (None: not in the log)
                if fault not in first or (evaluation is not None and (first[fault] is None or evaluation < first[fault])):
                    first[fault] = evaluation
            writer.writerow([name, "fail" if name in failed["none"] else "pass"] +
                            ["fail" if name in failed[fault] else "pass" for fault in faults] +
                            [" ".join(reveals), evaluation or ""])
    return {"recall": round(len(first) / len(faults), 3), "revealed": sorted(first),
            "first_per_fault": {fault: first.get(fault) for fault in faults}}


def shrink_into_corpus(out, hunted_set, failing, config_path):
    """Shrinks the hunted set's failing PPPs through ROS into a corpus; the number of distinct traps."""
    failing_dir, corpus = os.path.join(out, "hunted_failing"), os.path.join(out, "corpus")
    os.makedirs(failing_dir, exist_ok=True)
    for row in failing:
        shutil.copy(os.path.join(out, "sets", hunted_set, row["file"]), failing_dir)
    roslaunch("shrink.launch", ["input:=" + failing_dir, "agent:=" + AGENT, "config:=" + config_path,
                                "output:=" + os.path.join(out, "shrunk"), "corpus:=" + corpus,
                                "args:=--runs 1"], os.path.join(out, "shrink.log"))
    return len(glob.glob(os.path.join(corpus, "*.ppp")))


def run(route, planner, work, evaluations, shipped):
    out = os.path.join(work, planner, route)
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(os.path.dirname(out), exist_ok=True)
    config_path = out + ".yaml"
    with open(config_path, "w") as f:
        yaml.safe_dump(route_config(route, planner, evaluations, shipped), f, sort_keys=False)
    seconds = roslaunch("experiment.launch", ["output_dir:=" + out, "config:=" + config_path], out + ".log")
    with open(shipped) as f:
        size = next(s for s in yaml.safe_load(f)["sets"] if s["name"] == "hunted_" + AGENT)["generator"].get(
            "population", 60)
    return measure(route, planner, out, seconds, config_path, size)


def markdown_table(jsonl):
    """The figures of a hunt_power.jsonl as BENCHMARKS.md's tables: the single faults and MRPT's planner, the
    three-fault sample with its recall, then the totals per route."""
    rows = [json.loads(line) for line in open(jsonl)]

    def first(r):
        return "none" if r["first_failing_evaluation"] is None else "%d, %.1f s" % (r["first_failing_evaluation"],
                                                                                 r["first_failing_seconds"])

    lines = ["| planner | route | broken | hunted set fails | `turns` fails | evaluations | first failing: evaluation, "
             "seconds | failing PPPs per 1,000 evaluations | distinct traps | signatures | wall time |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        if len(faults_of(r["planner"])) > 1:
            continue
        lines.append("| %s | %s | %s | %.0f %% | %.0f %% | %d | %s | %.1f | %d | %d | %.0f s |" % (
            r["planner"], r["route"], "yes" if r["broken"] else "no", 100 * r["hunted_failure"],
            100 * r["reference_failure"], r["evaluations"], first(r), r["failing_per_1000"], r["traps"],
            r.get("signatures", 0), r["seconds"]))
    lines += ["", "| planner (three faults) | route | recall | revealed | first hunted PPP revealing each fault: "
              "evaluation | hunted set fails | failing PPPs per 1,000 evaluations | distinct traps | signatures |",
              "|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        if len(faults_of(r["planner"])) < 2:
            continue
        firsts = ", ".join("%s %s" % (f, "none" if e is None else e) for f, e in r["first_per_fault"].items())
        lines.append("| %s | %s | %d of 3 | %s | %s | %.0f %% | %.1f | %d | %d |" % (
            r["planner"].replace("+", ", "), r["route"], round(3 * r["recall"]), ", ".join(r["revealed"]) or "none",
            firsts, 100 * r["hunted_failure"], r["failing_per_1000"], r["traps"], r["signatures"]))
    lines.append("")
    for route in ROUTES:
        zoo = [r for r in rows if r["route"] == route and r["planner"] in ZOO_FAULTS]
        if zoo:
            found = sum(r["failing_per_1000"] * r["evaluations"] / 1000 for r in zoo)
            evaluations = sum(r["evaluations"] for r in zoo)
            lines.append("%s over the zoo: %d of %d faults broken, %.1f failing PPPs per 1,000 evaluations, %d traps" % (
                route, sum(r["broken"] for r in zoo), len(zoo), 1000 * found / evaluations,
                sum(r["traps"] for r in zoo)))
    for route in ROUTES:
        sample = [r for r in rows if r["route"] == route and len(faults_of(r["planner"])) > 1]
        if sample:
            revealed = sum(len(r["revealed"]) for r in sample)
            found = sum(r["failing_per_1000"] * r["evaluations"] / 1000 for r in sample)
            evaluations = sum(r["evaluations"] for r in sample)
            lines.append("%s over the three-fault sample: fault recall %.0f %% (%d of %d faults revealed), %.1f failing "
                         "PPPs per 1,000 evaluations, %d traps" % (route, 100.0 * revealed / (3 * len(sample)), revealed,
                                                                  3 * len(sample), 1000 * found / evaluations,
                                                                  sum(r["traps"] for r in sample)))
    lines.append("")
    lines += ["| planner | route | hunt wall time | ms an evaluation | steps an evaluation | µs a step |",
              "|---|---|---|---|---|---|"]
    for r in rows:
        if "us_per_step" in r:
            lines.append("| %s | %s | %.1f s | %.2f | %.1f | %.1f |" % (
                r["planner"].replace("+", ", "), r["route"], r["hunt_seconds"], r["ms_per_evaluation"],
                r["steps_per_evaluation"], r["us_per_step"]))
    lines.append("")
    for r in rows:
        if r["planner"] == "mrpt":
            lines.append("mrpt, %s: the hunted set's failed runs by diagnosis: %s" % (
                r["route"], ", ".join("%s %d" % kv for kv in sorted(r.get("diagnoses", {}).items())) or "none"))
    return "\n".join(lines)


def separation(work):
    """How well failure signatures tell the zoo's faults apart: each single-fault planner played once on the
    `turns` set and 1,000 random solvable PPPs; per fault its failed runs, their distinct signatures, and the share
    of its failed runs whose signature no other fault's runs showed; then per pair of faults the share of the
    first's failed runs whose signature the second also showed."""
    out = os.path.join(work, "separation")
    shutil.rmtree(out, ignore_errors=True)
    config = {"seed": 1, "runs": 1, "budget": 300, "sensor_range": 2,
              "agents": [agent_entry(f, f) for f in ZOO_FAULTS],
              "sets": [{"name": "random", "generator": {"fitness": "random", "population": 1000, "matings": 0,
                                                          "seed": 5}},
                       {"name": "turns", "generator": {"fitness": "turns", "matings": 10000, "seed": 1}}]}
    os.makedirs(work, exist_ok=True)
    with open(out + ".yaml", "w") as f:
        yaml.safe_dump(config, f, sort_keys=False)
    roslaunch("experiment.launch", ["output_dir:=" + out, "config:=" + out + ".yaml"], out + ".log")
    shown = collections.defaultdict(collections.Counter)  # fault -> signature -> failed runs
    for r in read_csv(os.path.join(out, "results.csv")):
        if r["pass"] == "0":
            shown[r["agent"]][r["signature"]] += 1
    lines = ["| fault | failed runs | distinct signatures | runs whose signature no other fault showed |",
             "|---|---:|---:|---:|"]
    for fault in ZOO_FAULTS:
        runs = sum(shown[fault].values())
        alone = sum(n for sig, n in shown[fault].items() if not any(sig in shown[o] for o in ZOO_FAULTS if o != fault))
        lines.append("| %s | %d | %d | %s |" % (fault, runs, len(shown[fault]),
                                              "%.0f %%" % (100.0 * alone / runs) if runs else "-"))
    lines += ["", "Share of the row fault's failed runs whose signature the column fault also showed:", "",
              "| | " + " | ".join(ZOO_FAULTS) + " |", "|---|" + "---:|" * len(ZOO_FAULTS)]
    for a in ZOO_FAULTS:
        runs = sum(shown[a].values())
        cells = []
        for b in ZOO_FAULTS:
            shared = sum(n for sig, n in shown[a].items() if sig in shown[b])
            cells.append("" if a == b else ("%.0f %%" % (100.0 * shared / runs) if runs else "-"))
        lines.append("| %s | %s |" % (a, " | ".join(cells)))
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--planners", default=",".join(PLANNERS), help="comma-separated (default: all)")
    parser.add_argument("--routes", default=",".join(ROUTES), help="comma-separated (default: all)")
    parser.add_argument("--work", default="/tmp/bench-hunt", help="where the runs are kept")
    parser.add_argument("--table", metavar="JSONL", help="print the table of a finished run's hunt_power.jsonl and exit")
    parser.add_argument("--separation", action="store_true",
                        help="measure how well failure signatures tell the zoo's faults apart, print it and exit")
    parser.add_argument("--config", default=os.path.join(ROOT, "config", "planner_hunt.yaml"),
                        help="the hunt config of the shipped route (default: config/planner_hunt.yaml)")
    args = parser.parse_args()
    if args.table:
        print(markdown_table(args.table))
        return 0
    if args.separation:
        print(separation(args.work))
        return 0
    routes = args.routes.split(",")
    # Until the shipped file changes, today's hunt is the shipped one: run once, reported for both.
    unchanged = subprocess.run(["git", "-C", ROOT, "diff", "--quiet", TODAY, "--", "config/planner_hunt.yaml"]).returncode == 0 \
        and os.path.samefile(args.config, os.path.join(ROOT, "config", "planner_hunt.yaml"))
    os.makedirs(args.work, exist_ok=True)
    open(os.path.join(args.work, "hunt_power.jsonl"), "w").close()  # this run's rows only
    for planner in args.planners.split(","):
        # Random search spends as many evaluations as the shipped hunt: it needs the shipped route's figures.
        shipped = run("shipped", planner, args.work, 0, args.config) if {"shipped", "random"} & set(routes) or \
            unchanged else None
        figures = [shipped] if "shipped" in routes else []
        if "today" in routes:
            figures.append(dict(shipped, route="today") if unchanged else run("today", planner, args.work, 0, args.config))
        if "random" in routes:
            figures.append(run("random", planner, args.work, shipped["evaluations"], args.config))
        with open(os.path.join(args.work, "hunt_power.jsonl"), "a") as log:
            for f in figures:
                print(json.dumps(f), flush=True)
                log.write(json.dumps(f) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
