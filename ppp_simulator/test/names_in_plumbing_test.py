#!/usr/bin/python3
"""No option's flag or parameter name is spelled by hand outside the plumbing that derives it from its declaration.

Every declared option (the tables of `ppp options`, docs/reference/options.md) reaches YAML, ROS parameters and flags through
its one declaration: flags are `--` plus the name (`_` and `.` as `-`), parameters `~` plus the name (`.` as `/`).
This test reads the declared names from `ppp options` and fails, naming file and line, on any non-test source that
reads a ROS parameter by a literal name instead of through a table, or names such a flag or parameter itself where
code acts on it: declaring a flag, asking whether one was given, or naming one in an error (prose in help texts
and docs may mention them; the generated docs/reference/options.md is tested against the tables).
Usage: names_in_plumbing_test.py REPOSITORY_ROOT PPP
"""
import os
import re
import subprocess
import sys
import unittest

ROOT = os.path.abspath(sys.argv.pop(1))
PPP = sys.argv.pop(1)

# The plumbing: where flags and parameters are derived from declarations (and the declarations' own docs).
PLUMBING = {
    'src/include/ppp_core/option_spec.hpp', 'src/include/ppp_core/option_yaml.hpp',
    'src/include/ppp_core/option_docs.hpp', 'src/cli/option_flags.hpp', 'ppp_msgs/include/ppp_msgs/node_parameters.h',
}
# Flags a command declares for itself that share a name with a declared option, each with why it is its own.
# An entry that no longer occurs fails the test too, so the list cannot go stale.
OWN_FLAGS = {
    ('ppp_generator/cli/generate_command.cpp', '--config'): "the generator YAML's path (the simulator's ~config is "
                                                            "the experiment YAML)",
    ('ppp_generator/cli/generate_command.cpp', '--threads'): "worker threads of this run (an experiment's `threads` "
                                                             "key is the experiment's); pace only",
    ('ppp_simulator/cli/launch_file_command.cpp', '--planner'): "AGENT=PACKAGE/EXECUTABLE, the planner to start (the "
                                                               "OMPL node's ~planner is its algorithm)",
    ('ppp_simulator/cli/scenarios_command.cpp', '--seed'): "the seed scenario seeds derive from",
    ('src/cli/random_command.cpp', '--obstacles'): "the number of random obstacle descriptors (the reactive node's "
                                                   "~obstacles is where its obstacle distances come from)",
    ('ppp_generator/cli/generate_command.cpp', '--output'): "the set directory it writes (a shrink's ~output is the "
                                                            "shrunk PPP)",
    ('ppp_simulator/cli/simulate_command.cpp', '--output'): "the replayed episode's picture or animation",
    ('ppp_simulator/cli/shrink_command.cpp', '--agent'): "the agent's type, or its name in --agents-file (the shrink "
                                                        "node's ~agent names an experiment's agent)",
    ('ppp_simulator/cli/shrink_command.cpp', '--any-kind'): "a switch without a value (the table's any_kind takes "
                                                           "true or false)",
    ('ppp_simulator/cli/shrink_command.cpp', '--agents-file'): "the agents file --agent is looked up in (a hunt's "
                                                              "agents_file holds its panel)",
    ('ppp_simulator/cli/shrink_command.cpp', '--runs'): "runs judged per candidate, seeded as ppp simulate seeds them",
    ('ppp_simulator/cli/shrink_command.cpp', '--seed'): "the failing run's seed, or the one the judged runs derive from",
    ('ppp_simulator/cli/simulate_command.cpp', '--runs'): "episodes of this one agent and PPP",
    ('ppp_simulator/cli/simulate_command.cpp', '--seed'): "the seed of those episodes (or of the replayed one)",
    ('src/cli/convert_command.cpp', '--resolution'): "metres per cell of the exported map; the core's commands "
                                                     "sit below the generator's tables",
    ('src/cli/convert_command.cpp', '--height'): "OctoMap extrusion height in metres (not a grid height)",
    ('src/cli/convert_command.cpp', '--start'): "start of an imported map; below the generator's tables",
    ('src/cli/convert_command.cpp', '--goal'): "goal of an imported map; below the generator's tables",
    ('src/cli/random_command.cpp', '--max-obstacles'): "obstacle budget of one random PPP; below the generator's tables",
    ('src/cli/random_command.cpp', '--seed'): "seed of one random PPP; below the generator's tables",
    ('src/cli/random_command.cpp', '--start'): "start of one random PPP; below the generator's tables",
    ('src/cli/random_command.cpp', '--goal'): "goal of one random PPP; below the generator's tables",
}
# A ROS parameter read by a literal name (not through ppp_msgs::readOptionParameters and a table).
LITERAL_READ = re.compile(r'\b(hasParam|getParam|searchParam|readParameter|param)\s*(<[^>]*>)?\s*\(\s*(\w+\s*,\s*)?"')


def declared_names():
    reference = subprocess.run([PPP, 'options'], stdout=subprocess.PIPE, universal_newlines=True, check=True).stdout
    names = set()
    for cell in re.findall(r'^\| `([^`]+)` \|', reference, re.M):
        names.add(cell.lstrip('~').replace('/', '.'))
    return names


def sources():
    listed = subprocess.run(['git', '-C', ROOT, 'ls-files', '--cached', '--others', '--exclude-standard',
                             '*.cpp', '*.hpp', '*.h', '*.py',
                             'ppp_simulator/scripts/*', 'ppp_agents/scripts/*'],
                            stdout=subprocess.PIPE, universal_newlines=True, check=True).stdout.split()
    for path in sorted(set(listed)):
        parts = path.split('/')
        if path in PLUMBING or {'test', 'fuzz', 'bench'} & set(parts) or not os.path.isfile(os.path.join(ROOT, path)):
            continue
        yield path


def acting_on(spellings):
    """Code acting on one of `spellings` by its literal: declaring it, asking for it, or naming it in an error."""
    names = '|'.join(re.escape(s) for s in sorted(spellings, key=len, reverse=True))
    return re.compile(r'\b(InvalidArgument|count|add_option|add_flag|given)\s*\(\s*"(' + names + r')(?![\w/-])')


def code_of(line):
    """The line without its // comment (a comment may name a flag)."""
    return re.sub(r'^\s*(//|#).*$|\s//.*$', '', line)


class NamesInPlumbingTest(unittest.TestCase):
    def test_no_declared_flag_or_parameter_is_spelled_by_hand(self):
        names = declared_names()
        self.assertGreater(len(names), 50)  # every table was read
        self.assertIn('connect_timeout', names)
        self.assertIn('weights.goal', names)
        spellings = sorted({'--' + n.replace('_', '-').replace('.', '-') for n in names} |
                           {'~' + n.replace('.', '/') for n in names}, key=len, reverse=True)
        spelled = acting_on(spellings)
        found = []
        seen = set()
        for path in sources():
            with open(os.path.join(ROOT, path), encoding='utf-8') as f:
                for number, line in enumerate(f, 1):
                    code = code_of(line)
                    for match in spelled.finditer(code):
                        if (path, match.group(2)) in OWN_FLAGS:
                            seen.add((path, match.group(2)))
                        else:
                            found.append('%s:%d: spells %s by hand' % (path, number, match.group(2)))
                    if LITERAL_READ.search(code):
                        found.append('%s:%d: reads a ROS parameter by a literal name' % (path, number))
        self.assertEqual(found, [], '\n' + '\n'.join(found))
        self.assertEqual(sorted(set(OWN_FLAGS) - seen), [], 'listed as a command\'s own flag but no longer there')

    def test_the_check_sees_a_spelled_flag_and_a_literal_read(self):
        spelled = acting_on(['--budget', '~budget'])
        self.assertTrue(spelled.search(code_of('  throw InvalidArgument("--budget", "x");')))
        self.assertTrue(spelled.search(code_of('  throw ppp::InvalidArgument("~budget", "x");')))
        self.assertTrue(spelled.search(code_of('  if (command.count("--budget") > 0) {')))
        self.assertTrue(spelled.search(code_of('  command->add_option("--budget", flags->budget, "moves");')))
        self.assertFalse(spelled.search(code_of('  // throw InvalidArgument("--budget", "x");')))
        self.assertFalse(spelled.search(code_of('  throw InvalidArgument("--budget-x", "x");')))
        self.assertFalse(spelled.search(code_of('  out << "give --budget to change it";')))
        self.assertTrue(LITERAL_READ.search('  readParameter(nh, "resolution", &p.resolution, "a number");'))
        self.assertTrue(LITERAL_READ.search('  if (!nh.hasParam("type")) throw x;'))
        self.assertFalse(LITERAL_READ.search('  readOptionParameters(nh, specs, &options);'))


if __name__ == '__main__':
    unittest.main()
