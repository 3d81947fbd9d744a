#!/usr/bin/python3
"""Plays an experiment over many seeds to show where its reference rates lie in the spread of its sets.

A set's pass rates depend on the one pool its seed evolves: under tournament replacement a set is 60 variations of
a few layouts, so the same options give sets whose rates differ by tens of points. A published table measured on
one set is one draw from such a spread. This script plays CONFIG once per seed with every option as CONFIG gives
it (each value keeps its text) but the seeds: the experiment's seed is the seed, and the evolved sets it keeps
take the seed, the seed + 1, and so on, in CONFIG's order. It keeps the sets CONFIG's `reference` names and the
sets those start their pool from (`initial_pool`). It prints, per seed, how many referenced rates its sets come
within the tolerance of; per set and agent (and for each set's mean optimal turns) the mean, the standard deviation
and the 5th to 95th percentile (nearest rank) over the seeds, and for referenced agents the share of sets below
the reference (ties count half); the most typical set, the one whose referenced rates lie nearest their mean over
the seeds (root mean square, in points), which stands for the options blind to the reference; how many seeds' sets
are within the tolerance of every reference; and the most typical of those. Writes WORK/spread.csv (seed, set,
agent, pass rate in %). Exit status 0, 1 when an experiment fails, 2 on bad usage or a CONFIG it cannot use.

Usage: scripts/seed_spread.py CONFIG [--seeds 1-200] [--runs N] [--tolerance POINTS] [--work DIR]
  --seeds      seeds as FIRST-LAST or a comma-separated list (default 1-9)
  --runs       runs per PPP of every agent without a `runs` key of its own (default 100)
  --tolerance  points a set's rate may lie from the reference (default 10)
  --work       directory for the seeds' experiments (default /tmp/ppp-seed-spread); not CONFIG's own
"""
import argparse
import csv
import math
import os
import shutil
import sys

import yaml

from experiment_runs import SEEDS_EXPECTED, parse_seeds, played_rates, run_experiment

TURNS = '*mean optimal turns*'  # the row of each set's mean optimal turns, beside its agents
SAME = 1e-9  # rates (%) this close are equal: a rate read back from summary.csv is not the decimal it stands for


def refuse(message):
    """Exits with status 2 and `message` (CONFIG or usage that cannot be played)."""
    print('seed_spread: ' + message, file=sys.stderr)
    sys.exit(2)


def mapping_value(node, key):
    """The value node of `key` in a YAML mapping node, or None."""
    return next((value for k, value in node.value if k.value == key), None)


def set_scalar(node, key, text, tag='tag:yaml.org,2002:int'):
    """Sets `key` of a YAML mapping node to a scalar of `text`, adding the key when it is missing."""
    scalar = yaml.ScalarNode(tag, text)
    for i, (k, _) in enumerate(node.value):
        if k.value == key:
            node.value[i] = (k, scalar)
            return
    node.value.append((yaml.ScalarNode('tag:yaml.org,2002:str', key), scalar))


class Config:
    """CONFIG read for playing over seeds: its text, its reference (percent by set and agent), the names of the
    sets to keep, in its order, and its directory."""

    def __init__(self, path):
        """Reads and checks CONFIG; refuses (exit 2) naming the file and key when it cannot be used."""
        self.path, self.directory = path, os.path.dirname(os.path.abspath(path))
        try:
            with open(path) as source:
                self.text = source.read()
            data = yaml.load(self.text, Loader=yaml.BaseLoader)  # every scalar as its text
        except (OSError, UnicodeDecodeError, yaml.YAMLError) as error:
            refuse('%s: cannot read it: %s' % (path, error))
        if not isinstance(data, dict) or not isinstance(data.get('reference'), dict) or not data['reference']:
            refuse('%s: no reference to compare with (expected reference: {SET: {AGENT: PERCENT}})' % path)
        self.reference = {}
        for set_name, rates in data['reference'].items():
            if not isinstance(rates, dict) or not rates:
                refuse('%s: reference.%s: expected {AGENT: PERCENT, ...}' % (path, set_name))
            for agent, text in rates.items():
                percent = self.number(text)
                if percent is None or not 0 <= percent <= 100:
                    refuse('%s: reference.%s.%s: expected a pass rate in percent (0 to 100), got %r'
                           % (path, set_name, agent, text))
                self.reference[(set_name, agent)] = percent
        sets = data.get('sets')
        if not isinstance(sets, list) or not all(isinstance(entry, dict) for entry in sets):
            refuse('%s: sets: expected a list of {name, generator} or {name, directory}' % path)
        self.sets = {}
        for i, entry in enumerate(sets):
            if entry.get('name') in self.sets:
                refuse('%s: sets[%d].name: %r names two sets' % (path, i, entry.get('name')))
            if 'generator' in entry and not isinstance(entry['generator'], dict):
                refuse('%s: sets[%d].generator: expected a mapping of generator options' % (path, i))
            self.sets[entry.get('name')] = entry
        wanted = set()
        for set_name in data['reference']:
            if set_name not in self.sets:
                refuse('%s: reference.%s: no set of that name in sets' % (path, set_name))
            if 'generator' not in self.sets[set_name]:
                refuse('%s: reference.%s: the set is read from a directory, the same PPPs whatever the seed, so it '
                       'has no spread across seeds (give it a generator)' % (path, set_name))
            wanted.add(set_name)
            pool = self.sets[set_name]['generator'].get('initial_pool')
            if pool in self.sets:
                wanted.add(pool)  # the set it starts from, played too
        self.kept = [name for name in self.sets if name in wanted]
        if isinstance(data.get('agents'), list):  # inline: check the names before playing anything
            names = {entry.get('name', entry.get('type')) for entry in data['agents'] if isinstance(entry, dict)}
            for set_name, agent in self.reference:
                if agent not in names:
                    refuse('%s: reference.%s.%s: no agent of that name in agents' % (path, set_name, agent))

    @staticmethod
    def number(text):
        """`text` as a finite number, or None."""
        try:
            value = float(text)
        except (TypeError, ValueError):
            return None
        return value if math.isfinite(value) else None

    def absolute(self, node):
        """A scalar node of a path: absolute against CONFIG's directory, as ppp reads it beside CONFIG."""
        if isinstance(node, yaml.ScalarNode) and node.value and not os.path.isabs(node.value):
            node.value = os.path.join(self.directory, node.value)
            node.tag, node.style = 'tag:yaml.org,2002:str', '"'

    def for_seed(self, seed, runs):
        """CONFIG's text for one seed: the kept sets only, the seeds set, paths made absolute."""
        root = yaml.compose(self.text, Loader=yaml.SafeLoader)
        set_scalar(root, 'seed', str(seed))
        set_scalar(root, 'runs', str(runs))
        set_scalar(root, 'hardest', '0')
        self.absolute(mapping_value(root, 'agents'))
        sets = mapping_value(root, 'sets')
        sets.value = [entry for entry in sets.value if mapping_value(entry, 'name').value in self.kept]
        evolved = 0
        for entry in sets.value:
            generator = mapping_value(entry, 'generator')
            if generator is None:
                self.absolute(mapping_value(entry, 'directory'))
                continue
            set_scalar(generator, 'seed', str(seed + evolved))
            evolved += 1
            pool = mapping_value(generator, 'initial_pool')
            if pool is not None and pool.value not in self.sets:
                self.absolute(pool)
        return yaml.serialize(root)


def nearest_rank(values, fraction):
    """The nearest-rank percentile of sorted `values`: the smallest value with at least `fraction` of them at or
    below it."""
    return values[max(0, math.ceil(fraction * len(values)) - 1)]


def summarize(played, reference, tolerance):
    """The report's lines for `played` ({seed: {(set, agent): rate}}, seeds in order) against `reference`
    ({(set, agent): percent}) with `tolerance` points."""
    seeds = list(played)
    keys = list(played[seeds[0]])
    mean = {k: sum(played[s][k] for s in seeds) / len(seeds) for k in keys}
    lines = ['| set | agent | reference | mean | sd | 5th - 95th percentile | sets below the reference |',
             '|---|---|---:|---:|---:|---:|---:|']
    for key in keys:
        values = sorted(played[s][key] for s in seeds)
        sd = (sum((v - mean[key]) ** 2 for v in values) / max(1, len(values) - 1)) ** 0.5
        wanted, below = reference.get(key), ''
        if wanted is not None:
            ties = sum(abs(v - wanted) <= SAME for v in values)
            below = '%.0f %%' % (100 * (sum(v < wanted - SAME for v in values) + 0.5 * ties) / len(values))
        lines.append('| %s | %s | %s | %.2f | %.2f | %.1f - %.1f | %s |' % (
            key[0], key[1], '' if wanted is None else '%.2f' % wanted, mean[key], sd, nearest_rank(values, 0.05),
            nearest_rank(values, 0.95), below))
    referenced = [k for k in keys if k in reference]
    distance = {s: (sum((played[s][k] - mean[k]) ** 2 for k in referenced) / len(referenced)) ** 0.5 for s in seeds}
    typical = min(seeds, key=lambda s: distance[s])
    lines.append('')
    lines.append('The most typical set: seed %d (its rates %.1f points from the mean over the seeds, root mean '
                 'square; blind to the reference)' % (typical, distance[typical]))
    within_all = [s for s in seeds if all(abs(played[s][k] - reference[k]) <= tolerance + SAME for k in referenced)]
    lines.append('Sets within %g points of every reference: %d of %d%s' % (
        tolerance, len(within_all), len(seeds), ' (seeds %s)' % ', '.join(map(str, within_all)) if within_all else ''))
    if within_all:
        typical = min(within_all, key=lambda s: distance[s])
        lines.append('The most typical of them: seed %d (%.1f points from the mean)' % (typical, distance[typical]))
    return lines


def main():
    """Plays CONFIG over the seeds, writes WORK/spread.csv and prints the spread."""
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('config')
    parser.add_argument('--seeds', default='1-9')
    parser.add_argument('--runs', type=int, default=100)
    parser.add_argument('--tolerance', type=float, default=10.0)
    parser.add_argument('--work', default='/tmp/ppp-seed-spread')
    args = parser.parse_args()
    seeds = parse_seeds(args.seeds)
    if seeds is None:
        parser.error('--seeds: %s, got %r' % (SEEDS_EXPECTED, args.seeds))
    if args.runs < 1:
        parser.error('--runs: expected at least 1, got %d' % args.runs)
    if not (math.isfinite(args.tolerance) and args.tolerance >= 0):
        parser.error('--tolerance: expected points >= 0, got %g' % args.tolerance)
    config = Config(args.config)
    if os.path.abspath(args.work) == config.directory:
        parser.error('--work: %s is the directory of CONFIG; give another' % args.work)
    os.makedirs(args.work, exist_ok=True)
    defaults, copied = os.path.join(config.directory, 'generator.yaml'), os.path.join(args.work, 'generator.yaml')
    if os.path.exists(defaults):
        shutil.copy(defaults, copied)  # the sets' generator defaults, read beside each seed's config as beside CONFIG
    elif os.path.exists(copied):
        os.remove(copied)  # an earlier CONFIG's
    played = {}
    with open(os.path.join(args.work, 'spread.csv'), 'w', newline='') as out:
        writer = csv.writer(out)
        writer.writerow(['seed', 'set', 'agent', 'pass_rate'])
        for seed in seeds:
            directory = os.path.join(args.work, 'seed_%d' % seed)
            run_experiment(config.for_seed(seed, args.runs), directory, 'seed_spread')
            played[seed] = {}
            for set_name in config.kept:
                rates, _, turns = played_rates(directory, set_name)
                writer.writerows([seed, set_name, agent, '%.4f' % rate] for agent, rate in rates.items())
                played[seed].update({(set_name, agent): rate for agent, rate in rates.items()})
                played[seed][(set_name, TURNS)] = turns
            out.flush()
            within = sum(abs(played[seed][k] - v) <= args.tolerance + SAME for k, v in config.reference.items())
            named = (lambda k: k[1]) if len({k[0] for k in config.reference}) == 1 else '/'.join
            print('seed %d: %d of %d within %g points  %s' % (seed, within, len(config.reference), args.tolerance,
                  ', '.join('%s %.1f' % (named(k), played[seed][k]) for k in config.reference)), flush=True)
    print('\n%d seeds, %d runs per PPP: the sets\' pass rates (%%) against the reference' % (len(seeds), args.runs))
    print('\n'.join(summarize(played, config.reference, args.tolerance)))
    return 0


if __name__ == '__main__':
    sys.exit(main())
