"""What scripts/calibrate.py and scripts/seed_spread.py share: parsing --seeds, running `ppp experiment` on a
written config, and reading the pass rates it wrote."""
import csv
import os
import shutil
import subprocess
import sys

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# At most this many seeds in one --seeds, each below SEED_LIMIT (a set's generator seed may add a few to it).
MAX_SEEDS = 10000
SEED_LIMIT = 2 ** 62


def parse_seeds(text):
    """The seeds of a --seeds value ('1-200' or '1,2,3'), or None unless they are distinct integers in
    [0, SEED_LIMIT), at most MAX_SEEDS of them."""
    try:
        if '-' in text:
            first, last = (int(part) for part in text.split('-'))
            if not 0 <= first <= last < SEED_LIMIT or last - first >= MAX_SEEDS:
                return None
            return list(range(first, last + 1))
        seeds = [int(part) for part in text.split(',')]
    except ValueError:
        return None
    if len(set(seeds)) != len(seeds) or len(seeds) > MAX_SEEDS or not all(0 <= s < SEED_LIMIT for s in seeds):
        return None
    return seeds


SEEDS_EXPECTED = ('expected FIRST-LAST or distinct integers separated by commas, each in [0, 2^62), at most %d'
                  % MAX_SEEDS)


def run_experiment(config_text, directory, prefix):
    """Writes `config_text` to DIRECTORY.yaml and runs `ppp experiment` on it into `directory` (emptied first);
    on failure exits with status 1 and ppp's message, `prefix` first."""
    shutil.rmtree(directory, ignore_errors=True)
    with open(directory + '.yaml', 'w') as config:
        config.write(config_text)
    completed = subprocess.run([os.path.join(REPO, 'scripts', 'ppp'), 'experiment', directory + '.yaml', '-o',
                                directory, '--quiet'], capture_output=True, text=True)
    if completed.returncode != 0:
        print('%s: ppp experiment failed on %s.yaml: %s' % (prefix, directory, completed.stderr.strip()[-500:]),
              file=sys.stderr)
        sys.exit(1)


def played_rates(directory, set_name='turns'):
    """Set-level pass rates (%) and per-PPP pass rates (%, in PPP order) per agent on one set of a finished
    experiment, and the set's mean optimal turns."""
    rates, per_ppp = {}, {}
    with open(os.path.join(directory, 'summary.csv')) as summary:
        for row in csv.DictReader(summary):
            if row['set'] != set_name:
                continue
            if row['level'] == 'set':
                rates[row['agent']] = 100 * float(row['pass_rate'])
            elif row['level'] == 'problem':
                per_ppp.setdefault(row['agent'], []).append(100 * float(row['pass_rate']))
    with open(os.path.join(directory, 'sets', set_name, 'set.csv')) as characters:
        turns = [float(row['turns']) for row in csv.DictReader(characters)]
    return rates, per_ppp, sum(turns) / len(turns)
