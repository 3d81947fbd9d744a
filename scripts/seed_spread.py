#!/usr/bin/python3
"""Plays an experiment over many seeds to show where its reference rates lie in the spread of its sets.

A set's pass rates depend on the one pool its seed evolves: under tournament replacement a set is 60 variations of
a few layouts, so the same options give sets whose rates differ by tens of points. A published table measured on
one set is one draw from such a spread. This script plays CONFIG once per seed: the experiment's seed and the
generator seed of each set that CONFIG's `reference` names are the seed (the second such set's seed + 1, and so
on); sets without a reference are left out; every other option is CONFIG's. It prints, per seed, how many
referenced rates its sets come within the tolerance of; per set and agent the mean, standard deviation and 5th to
95th percentile of the sets' rates and the share of sets below the reference (ties count half); the most typical
set, the one whose rates lie nearest their mean over all the seeds (root mean square over the referenced agents),
which stands for the options blind to the reference; how many seeds' sets are within the tolerance of every
reference; and the most typical of those. Writes WORK/spread.csv (seed, set, agent, pass rate in %). Exit status 0,
1 when an experiment fails, 2 on bad usage or a CONFIG it cannot use.

Usage: scripts/seed_spread.py CONFIG [--seeds 1-200] [--runs N] [--tolerance POINTS] [--work DIR]
  --seeds      seeds as FIRST-LAST or a comma-separated list (default 1-9)
  --runs       runs per agent per PPP (default 100)
  --tolerance  points a set's rate may lie from the reference (default 10)
  --work       directory for the seeds' experiments (default /tmp/ppp-seed-spread)
"""
import argparse
import csv
import os
import re
import shutil
import subprocess
import sys

import yaml

from calibrate import played_rates

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MAX_SEEDS = 10000


class ConfigLoader(yaml.SafeLoader):
    """YAML 1.2's booleans only (true, false), so values such as `goal_seeking: on` stay the words they are."""


ConfigLoader.yaml_implicit_resolvers = {
    first: [(tag, pattern) for tag, pattern in resolvers if tag != 'tag:yaml.org,2002:bool']
    for first, resolvers in yaml.SafeLoader.yaml_implicit_resolvers.items()}
ConfigLoader.add_implicit_resolver('tag:yaml.org,2002:bool', re.compile(r'^(?:true|True|TRUE|false|False|FALSE)$'),
                                   list('tTfF'))


def parse_seeds(text):
    """The seeds of --seeds ('1-200' or '1,2,3'), or None when the text is neither."""
    try:
        if '-' in text:
            first, last = (int(part) for part in text.split('-'))
            return list(range(first, last + 1)) if 0 <= first <= last else None
        seeds = [int(part) for part in text.split(',')]
        return seeds if all(s >= 0 for s in seeds) and len(set(seeds)) == len(seeds) else None
    except ValueError:
        return None


def referenced_config(path):
    """CONFIG as a mapping with only the referenced sets, and its reference; exits 2 naming the file and key
    when it has no usable reference."""
    try:
        with open(path) as source:
            config = yaml.load(source, Loader=ConfigLoader)
    except (OSError, yaml.YAMLError) as error:
        sys.exit('seed_spread: %s: cannot read it: %s' % (path, error))
    if not isinstance(config, dict) or not isinstance(config.get('reference'), dict) or not config['reference']:
        sys.exit('seed_spread: %s: no reference to compare with (expected reference: {SET: {AGENT: PERCENT}})'
                 % path)
    reference = config['reference']
    for set_name, rates in reference.items():
        if not isinstance(rates, dict) or not rates:
            sys.exit('seed_spread: %s: reference.%s: expected {AGENT: PERCENT, ...}' % (path, set_name))
        for agent, percent in rates.items():
            if isinstance(percent, bool) or not isinstance(percent, (int, float)) or not 0 <= percent <= 100:
                sys.exit('seed_spread: %s: reference.%s.%s: expected a pass rate in percent (0 to 100), got %r'
                         % (path, set_name, agent, percent))
    sets = {entry.get('name'): entry for entry in config.get('sets') or [] if isinstance(entry, dict)}
    for name in reference:
        if name not in sets:
            sys.exit('seed_spread: %s: reference.%s: no set of that name in sets' % (path, name))
        if 'generator' not in sets[name]:
            sys.exit('seed_spread: %s: reference.%s: the set is read from a directory, the same PPPs whatever the '
                     'seed, so it has no spread across seeds (give it a generator)' % (path, name))
    config['sets'] = [sets[name] for name in reference]
    here = os.path.dirname(os.path.abspath(path))
    if isinstance(config.get('agents'), str):
        config['agents'] = os.path.join(here, config['agents'])  # a file beside CONFIG
    return config, reference, os.path.join(here, 'generator.yaml')


def play(config, seed, runs, work):
    """The set-level pass rates (%) by (set, agent) of CONFIG played with `seed`."""
    config = dict(config, seed=seed, runs=runs, hardest=0)
    config['sets'] = [dict(entry, generator=dict(entry['generator'], seed=seed + index))
                      for index, entry in enumerate(config['sets'])]
    config.pop('reference')
    directory = os.path.join(work, 'seed_%d' % seed)
    shutil.rmtree(directory, ignore_errors=True)
    with open(directory + '.yaml', 'w') as out:
        yaml.safe_dump(config, out, sort_keys=False)
    done = subprocess.run([os.path.join(REPO, 'scripts', 'ppp'), 'experiment', directory + '.yaml', '-o', directory,
                           '--quiet'], capture_output=True, text=True)
    if done.returncode != 0:
        print('seed_spread: ppp experiment failed on %s.yaml: %s' % (directory, done.stderr.strip()[-500:]),
              file=sys.stderr)
        sys.exit(1)
    rates = {}
    for entry in config['sets']:
        set_rates = played_rates(directory, entry['name'])[0]
        rates.update({(entry['name'], agent): rate for agent, rate in set_rates.items()})
    return rates


def percentile(values, fraction):
    """The value below which `fraction` of the sorted `values` lie (nearest rank)."""
    return values[min(len(values) - 1, int(fraction * len(values)))]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('config')
    parser.add_argument('--seeds', default='1-9')
    parser.add_argument('--runs', type=int, default=100)
    parser.add_argument('--tolerance', type=float, default=10.0)
    parser.add_argument('--work', default='/tmp/ppp-seed-spread')
    args = parser.parse_args()
    seeds = parse_seeds(args.seeds)
    if seeds is None or not 1 <= len(seeds) <= MAX_SEEDS:
        parser.error('--seeds: expected FIRST-LAST or distinct non-negative integers separated by commas, at most '
                     '%d seeds, got %r' % (MAX_SEEDS, args.seeds))
    if args.runs < 1:
        parser.error('--runs: expected at least 1, got %d' % args.runs)
    if args.tolerance < 0:
        parser.error('--tolerance: expected points >= 0, got %g' % args.tolerance)
    config, reference, generator_defaults = referenced_config(args.config)
    keys = [(set_name, agent) for set_name, agents in reference.items() for agent in agents]
    os.makedirs(args.work, exist_ok=True)
    if os.path.exists(generator_defaults):
        shutil.copy(generator_defaults, os.path.join(args.work, 'generator.yaml'))  # the sets' defaults, as beside
    played = {}
    with open(os.path.join(args.work, 'spread.csv'), 'w', newline='') as out:
        writer = csv.writer(out)
        writer.writerow(['seed', 'set', 'agent', 'pass_rate'])
        for seed in seeds:
            rates = play(config, seed, args.runs, args.work)
            missing = [key for key in keys if key not in rates]
            if missing:
                sys.exit('seed_spread: %s: reference.%s.%s: no agent of that name in the experiment'
                         % ((args.config,) + missing[0]))
            played[seed] = {key: rates[key] for key in keys}
            writer.writerows([seed, s, a, '%.4f' % rates[(s, a)]] for s, a in sorted(rates))
            out.flush()
            within = sum(abs(played[seed][k] - reference[k[0]][k[1]]) <= args.tolerance for k in keys)
            print('seed %d: %d of %d within %g points  %s' % (seed, within, len(keys), args.tolerance, ', '.join(
                '%s %.1f' % (a, played[seed][(s, a)]) for s, a in keys)), flush=True)
    mean = {k: sum(played[s][k] for s in seeds) / len(seeds) for k in keys}
    print('\n%d seeds, %d runs per PPP: the sets\' pass rates (%%) against the reference' % (len(seeds), args.runs))
    print('| set | agent | reference | mean | sd | 5th - 95th percentile | share of sets below the reference |')
    print('|---|---|---:|---:|---:|---:|---:|')
    for set_name, agent in keys:
        values = sorted(played[s][(set_name, agent)] for s in seeds)
        sd = (sum((v - mean[(set_name, agent)]) ** 2 for v in values) / max(1, len(values) - 1)) ** 0.5
        wanted = reference[set_name][agent]
        below = (sum(v < wanted for v in values) + 0.5 * sum(v == wanted for v in values)) / len(values)
        print('| %s | %s | %.2f | %.2f | %.2f | %.1f - %.1f | %.0f %% |' % (
            set_name, agent, wanted, mean[(set_name, agent)], sd, percentile(values, 0.05), percentile(values, 0.95),
            100 * below))
    distance = {s: (sum((played[s][k] - mean[k]) ** 2 for k in keys) / len(keys)) ** 0.5 for s in seeds}
    typical = min(seeds, key=lambda s: distance[s])
    print('\nThe most typical set: seed %d (its rates %.1f points from the mean over the seeds, root mean square; '
          'blind to the reference)' % (typical, distance[typical]))
    close = [s for s in seeds if all(abs(played[s][k] - reference[k[0]][k[1]]) <= args.tolerance for k in keys)]
    print('Sets within %g points of every reference: %d of %d%s' % (
        args.tolerance, len(close), len(seeds), ' (seeds %s)' % ', '.join(map(str, close)) if close else ''))
    if close:
        typical = min(close, key=lambda s: distance[s])
        print('The most typical of them: seed %d (%.1f points from the mean)' % (typical, distance[typical]))
    return 0


if __name__ == '__main__':
    sys.exit(main())
