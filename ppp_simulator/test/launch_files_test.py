#!/usr/bin/python3
"""The shipped launch files, and the graphs `ppp launch-file` writes from experiment configs.

launch/experiment.launch starts one node, ppp_simulator/experiment_launcher, with absolute paths and the
arguments. The graph of config/experiment.yaml holds one agent node per built-in agent of config/agents.yaml
(node name = the agent's ROS name, ~type/~memory/~sensor_noise as in the file, topics /NAME/scans and
/NAME/moves), a bridge and its planner per instance of a planner agent (one per core for a planner the
experiment starts, each in /NAME/instance_K when there are several), one generator node per set with that set's options,
and the simulator taking the sets from them; a small config's graph holds only its own nodes, on the hosts it
names. launch/inspect.launch must load with and without a bag. A hunt's graph holds its set's generator node,
the simulator in hunt mode and the nodes of the panel's agents only; a shrink's, the shrink node, the simulator in
hunt mode and the nodes of its agent only.
Loads everything with roslaunch's own parser; starts nothing. Usage: launch_files_test.py REPOSITORY_ROOT PPP
"""
import os
import json
import re
import shlex
import subprocess
import sys
import tempfile
import unittest

import roslaunch.config
import yaml

ROOT = os.path.abspath(sys.argv.pop(1))
PPP = sys.argv.pop(1)


def graph_name(name):
    """ppp::agents::agentGraphName: the agent name as a legal ROS name."""
    prefixed = name if re.match('[A-Za-z]', name) else 'agent_' + name
    return re.sub('[^A-Za-z0-9_]', '_', prefixed)


def instance_namespaces(name, count):
    """The namespaces of a planner agent's instances (ppp::agents::instanceGraphName)."""
    if count == 1:
        return ['/%s/' % graph_name(name)]
    return ['/%s/instance_%d/' % (graph_name(name), k) for k in range(1, count + 1)]


# The executable each of the graph's nodelet types wraps: a nodelet and its node play the same role.
NODELET_EXECUTABLES = {'ppp_agents/Agent': 'agent_node', 'ppp_generator/Generator': 'generator_node',
                       'ppp_simulator/Simulator': 'simulator_node', 'ppp_agents/PlannerBridge': 'planner_bridge_node',
                       'ppp_agents/OptimisticPlanner': 'optimistic_planner_node',
                       'ppp_agents/OmplPlanner': 'ompl_planner_node', 'ppp_agents/MrptPlanner': 'mrpt_planner_node',
                       'ppp_agents/MrptReactive': 'mrpt_reactive_node', 'ppp_agents/DwaPlanner': 'dwa_planner_node',
                       'ppp_agents/EchoPlanner': 'echo_planner_node'}


def nodelet_of(node):
    """The nodelet type a `nodelet load TYPE MANAGER --no-bond [ARGS]` node loads, or None."""
    args = node.args.split()
    if node.type != 'nodelet' or len(args) < 4 or args[0] != 'load':
        return None
    # The manager's name resolves in the node's namespace: absolute from any other than the root.
    manager = 'nodelet_manager' if node.namespace == '/' else '/nodelet_manager'
    assert args[2:4] == [manager, '--no-bond'], node.args
    return args[1]


def node_args(node):
    """The arguments a node, or the nodelet it loads, is given (private parameters as _NAME:=VALUE)."""
    return ' '.join(node.args.split()[4:]) if nodelet_of(node) else node.args


def role(node):
    """The executable a node runs, or the one its nodelet wraps."""
    return NODELET_EXECUTABLES[nodelet_of(node)] if nodelet_of(node) else node.type


def executable(node):
    """PACKAGE/EXECUTABLE of a node, or of the executable its nodelet wraps."""
    return (nodelet_of(node).split('/')[0] if nodelet_of(node) else node.package) + '/' + role(node)


# Instances of a planner the experiment starts, when the config does not say (ppp::agents::instanceCount).
CORES = min(max(os.cpu_count() or 1, 1), 64)


def load(launch, *args):
    # The launch files resolve relative paths against $PWD, as a shell keeps it; ctest changes directory without.
    os.environ['PWD'] = os.getcwd()
    path = os.path.join(ROOT, 'launch', launch)
    return roslaunch.config.load_config_default([(path, list(args))], None, assign_machines=False)


def launch_file(config, *flags):
    """What `ppp launch-file CONFIG -o DIR FLAGS` prints, and its exit status and errors."""
    out = os.path.join(tempfile.mkdtemp(), 'out')
    result = subprocess.run([PPP, 'launch-file', config, '-o', out] + list(flags), stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, universal_newlines=True)
    return result.stdout, result.returncode, result.stderr, out


def load_graph(config, *flags):
    xml, status, errors, out = launch_file(config, *flags)
    if status != 0:
        raise AssertionError('ppp launch-file failed: ' + errors)
    return roslaunch.config.load_config_default([], None, roslaunch_strs=[xml], assign_machines=False), out


def small_config(explorer_options):
    """A config of one small evolved set and two agents, the explorer with `explorer_options` (YAML flow text)."""
    return """
seed: 5
runs: 3
agents:
  - {name: astar, type: astar}
  - {name: explorer, type: explorer, %s}
sets:
  - name: mine
    generator: {fitness: advances, population: 6, matings: 50, seed: 4}
""" % explorer_options


def write_config(directory, text):
    path = os.path.join(directory, 'experiment.yaml')
    with open(path, 'w') as f:
        f.write(text)
    return path


class ExperimentLaunchTest(unittest.TestCase):
    def test_the_entry_runs_the_launcher_with_absolute_paths_and_the_flags_as_given(self):
        flags = '--step-timeout 2 --batch-size 7 --record false --planner mine=ppp_agents/simple_planner.py'
        config = load('experiment.launch', 'output_dir:=relative/out', 'args:=' + flags)
        self.assertEqual([(n.package, n.type, n.name) for n in config.nodes],
                         [('ppp_simulator', 'experiment_launcher', 'experiment')])
        launcher = config.nodes[0]
        self.assertTrue(launcher.required)
        args = shlex.split(launcher.args)
        value = lambda flag: args[args.index(flag) + 1]
        self.assertEqual(value('--output-dir'), os.path.join(os.getcwd(), 'relative', 'out'))
        self.assertEqual(os.path.realpath(value('--config')), os.path.join(ROOT, 'config', 'experiment.yaml'))
        self.assertEqual(value('--removed').split()[0], 'batch_size=')
        self.assertIn('--args=' + flags, args)

    def test_the_launch_files_write_no_default_of_a_flag(self):
        # Every setting beyond config, output_dir (and a hunt's set) is a `ppp launch-file` flag, whose default is
        # declared once; the arguments of earlier versions default to nothing and are refused when given.
        for launch in ('experiment.launch', 'hunt.launch'):
            with open(os.path.join(ROOT, 'launch', launch)) as f:
                text = f.read()
            defaults = dict(re.findall(r'<arg name="([a-z_]+)" default="([^"]*)"', text))
            kept = {'config', 'args'} | ({'set'} if launch == 'hunt.launch' else set())
            self.assertEqual({k: v for k, v in defaults.items() if v and k not in kept}, {}, launch)
            self.assertIn('doc="removed: see args"', text)

    def test_an_argument_of_an_earlier_version_is_refused_naming_its_flag(self):
        launcher = os.path.join(ROOT, 'ppp_simulator', 'scripts', 'experiment_launcher')
        for removed, flag in (('batch_size=7', '--batch-size 7'), ('planner=mine', '--planner AGENT=')):
            result = subprocess.run(['/usr/bin/python3', launcher, '--config', 'x.yaml', '--output-dir', '/tmp/x',
                                     '--removed', removed + ' record='], stdout=subprocess.PIPE,
                                    stderr=subprocess.PIPE, universal_newlines=True)
            self.assertEqual(result.returncode, 1, result.stderr)
            self.assertIn(removed.split('=')[0] + ':= is no longer an argument', result.stderr)
            self.assertIn('args:="' + flag, result.stderr)

    def test_generate_launch_takes_its_options_from_the_config(self):
        config = load('generate.launch')
        params = {k: p.value for k, p in config.params.items()}
        with open(os.path.join(ROOT, 'config', 'generator.yaml')) as f:
            defaults = yaml.safe_load(f)
        self.assertEqual(params['/generator/fitness'], defaults['fitness'])
        self.assertEqual(params['/generator/seed'], defaults['seed'])
        self.assertNotIn('/generator/output_dir', params)
        directory = tempfile.mkdtemp()
        mine = os.path.join(directory, 'mine.yaml')
        with open(mine, 'w') as f:
            f.write('fitness: difficulty\nseed: 9\n')
        params = {k: p.value for k, p in load('generate.launch', 'config:=' + mine, 'output_dir:=/tmp/x').params.items()}
        self.assertEqual((params['/generator/fitness'], params['/generator/seed']), ('difficulty', 9))
        self.assertEqual(params['/generator/output_dir'], '/tmp/x')
        params = {k: p.value for k, p in load('generate.launch', 'fitness:=advances', 'seed:=3').params.items()}
        self.assertEqual((params['/generator/fitness'], params['/generator/seed']), ('advances', 3))


class DefaultGraphTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.config, cls.out = load_graph(os.path.join(ROOT, 'config', 'experiment.yaml'))
        cls.nodes = {n.name: n for n in cls.config.nodes}
        cls.params = {k: p.value for k, p in cls.config.params.items()}
        with open(os.path.join(ROOT, 'config', 'experiment.yaml')) as f:
            cls.experiment = yaml.safe_load(f)
        with open(os.path.join(ROOT, 'config', cls.experiment['agents'])) as f:
            cls.agents = yaml.safe_load(f)['agents']

    def test_one_agent_node_per_configured_agent(self):
        built_in = [a for a in self.agents if a['type'] != 'planner']
        agent_nodes = sorted(n.name for n in self.config.nodes if role(n) == 'agent_node')
        self.assertEqual(agent_nodes, sorted(graph_name(a['name']) for a in built_in))
        for agent in built_in:
            node_name = graph_name(agent['name'])
            node = self.nodes[node_name]
            self.assertEqual(nodelet_of(node), 'ppp_agents/Agent')
            self.assertEqual(node.namespace, '/')
            self.assertIsNone(node.machine_name)
            self.assertIn(['scans', '~scans'], [list(r) for r in node.remap_args])
            self.assertIn(['moves', '~moves'], [list(r) for r in node.remap_args])
            prefix = '/%s/' % node_name
            self.assertEqual(self.params[prefix + 'type'], agent['type'], node_name)
            self.assertEqual(self.params[prefix + 'memory'], agent.get('memory', 'full'), node_name)
            self.assertEqual(self.params[prefix + 'sensor_noise'], agent.get('sensor_noise', 0.0), node_name)
            self.assertEqual(self.params[prefix + 'name'], agent['name'], node_name)

    def test_one_bridge_and_its_planner_per_instance_of_a_planner_agent(self):
        planners = [a for a in self.agents if a['type'] == 'planner']
        self.assertEqual(len(planners), 8)
        bridges = sorted(n.namespace for n in self.config.nodes if role(n) == 'planner_bridge_node')
        self.assertEqual(bridges, sorted(ns for a in planners for ns in instance_namespaces(a['name'], CORES)))
        for agent in planners:
            for namespace in instance_namespaces(agent['name'], CORES):
                self.assertEqual(self.params[namespace + 'bridge/memory'], agent.get('memory', 'full'))
                self.assertEqual(self.params[namespace + 'bridge/name'], agent['name'])
                planner_nodes = [n for n in self.config.nodes if n.namespace == namespace + 'robot/']
                self.assertEqual([executable(n) for n in planner_nodes], [agent['planner_node']])
                nodelets = [k for k, v in NODELET_EXECUTABLES.items() if 'ppp_agents/' + v == agent['planner_node']]
                if agent.get('motion') == 'continuous':
                    # Told the robot it drives.
                    planner = namespace + 'robot/planner/'
                    self.assertEqual(self.params[planner + 'kinematics'], 'diff_drive')
                    self.assertEqual(self.params[planner + 'max_linear_speed'], 0.5)
                    self.assertEqual(self.params[planner + 'control_period'], 0.1)
                    self.assertEqual(self.params[planner + 'robot_radius'], 0.0)
                    clock = ['/clock', namespace + 'robot/clock']
                    if not nodelets:
                        # On simulated time: a process of its own (a process has one time) with its bridge's clock.
                        self.assertEqual([nodelet_of(n) for n in planner_nodes], [None])
                        self.assertIn(clock, [list(r) for r in planner_nodes[0].remap_args])
                        continue
                    # One that reads the time from its messages' stamps: a nodelet beside its bridge, no clock.
                    self.assertNotIn(clock, [list(r) for r in planner_nodes[0].remap_args])
                # The example planners are nodelets of the manager beside their bridges, asked in the simulator's
                # thread.
                self.assertEqual([nodelet_of(n) for n in planner_nodes], nodelets)
                # Each instance's bridge and planner talk tf in their namespace, not on the global /tf.
                bridge = [n for n in self.config.nodes if n.namespace == namespace and role(n) == 'planner_bridge_node']
                self.assertEqual([nodelet_of(n) for n in bridge], ['ppp_agents/PlannerBridge'])
                for node in bridge + planner_nodes:
                    self.assertIn(['/tf', namespace + 'tf'], [list(r) for r in node.remap_args])
                    self.assertIn(['/tf_static', namespace + 'tf_static'], [list(r) for r in node.remap_args])

    def test_one_generator_node_per_set_with_its_options(self):
        with open(os.path.join(ROOT, 'config', 'generator.yaml')) as f:
            defaults = yaml.safe_load(f)
        generators = sorted(n.name for n in self.config.nodes if role(n) == 'generator_node')
        self.assertEqual(generators, sorted('gen_' + s['name'] for s in self.experiment['sets']))
        for s in self.experiment['sets']:
            name = 'gen_' + s['name']
            self.assertIn(['problem_set', '~problem_set'], [list(r) for r in self.nodes[name].remap_args])
            options = yaml.safe_load(self.params['/%s/options' % name])
            for key, value in dict(defaults, **s['generator']).items():
                self.assertEqual(options[key], value, name + ' ' + key)
            self.assertEqual(self.params['/%s/set_name' % name], s['name'])
            self.assertIs(self.params['/%s/resume' % name], True)
            self.assertEqual(self.params['/%s/output_dir' % name], os.path.join(self.out, 'sets', s['name']))

    def test_the_simulator_takes_the_sets_from_the_generators_in_the_required_manager(self):
        # The manager ends the graph: the simulator's nodelet shuts it down when the experiment is done.
        self.assertEqual(nodelet_of(self.nodes['simulator']), 'ppp_simulator/Simulator')
        self.assertFalse(self.nodes['simulator'].required)
        manager = self.config.nodes[0]
        self.assertEqual((manager.name, manager.package, manager.type, manager.args, manager.required),
                         ('nodelet_manager', 'nodelet', 'nodelet', 'manager', True))
        self.assertEqual(self.params['/simulator/output_dir'], self.out)
        self.assertEqual(self.params['/simulator/config'], os.path.join(ROOT, 'config', 'experiment.yaml'))
        self.assertIs(self.params['/simulator/generator_nodes'], True)
        self.assertEqual(self.params['/simulator/batch_size'], 500)  # agents answer in the lanes' threads
        self.assertIsInstance(self.params['/simulator/step_timeout'], float)

    def test_the_json_graph_is_the_xml_graph_with_its_hosts_and_required_node(self):
        command = [PPP, 'launch-file', os.path.join(ROOT, 'config', 'experiment.yaml'), '-o', self.out]
        xml = subprocess.run(command, stdout=subprocess.PIPE, universal_newlines=True, check=True).stdout
        graph = json.loads(subprocess.run(command + ['--json'], stdout=subprocess.PIPE, universal_newlines=True,
                                          check=True).stdout)
        self.assertEqual(graph['xml'], xml)
        self.assertEqual(graph['required'], 'nodelet_manager')
        self.assertEqual(graph['status_param'], '/simulator/exit_status')
        self.assertEqual(graph['machines'], [])
        self.assertEqual(sorted(n['name'] for n in graph['nodes'] if n['type'] == 'agent_node'),
                         sorted(n.name for n in self.config.nodes if role(n) == 'agent_node'))

    def test_every_node_in_a_process_of_its_own_on_request(self):
        config, _ = load_graph(os.path.join(ROOT, 'config', 'experiment.yaml'), '--processes', 'own')
        types = sorted(set(n.type for n in config.nodes))
        self.assertEqual(types, ['agent_node', 'dwa_planner_node', 'generator_node', 'mrpt_planner_node',
                                 'mrpt_reactive_node', 'mrpt_tpspace_node', 'ompl_planner_node',
                                 'optimistic_planner_node', 'planner_bridge_node', 'simulator_node'])
        self.assertEqual([n.name for n in config.nodes if n.required], ['simulator'])
        self.assertEqual(config.params['/simulator/batch_size'].value, 2000)  # round trips between processes
        given, _ = load_graph(os.path.join(ROOT, 'config', 'experiment.yaml'), '--batch-size', '7')
        self.assertEqual(given.params['/simulator/batch_size'].value, 7)
        text, _, _, _ = launch_file(os.path.join(ROOT, 'config', 'experiment.yaml'), '--processes', 'own', '--json')
        self.assertEqual((json.loads(text)['required'], json.loads(text)['status_param']), ('simulator', ''))
        _, status, errors, _ = launch_file(os.path.join(ROOT, 'config', 'experiment.yaml'), '--processes', 'some')
        self.assertNotEqual(status, 0)
        self.assertIn("processes: expected manager or own, got 'some'", errors)

    def test_an_agent_may_run_in_a_process_of_its_own_beside_the_manager(self):
        directory = tempfile.mkdtemp()
        path = write_config(directory, small_config('process: own'))
        config, _ = load_graph(path)
        nodes = {n.name: n for n in config.nodes}
        self.assertEqual(nodelet_of(nodes['astar']), 'ppp_agents/Agent')
        self.assertEqual((nodes['explorer'].package, nodes['explorer'].type), ('ppp_agents', 'agent_node'))
        self.assertIsNone(nodelet_of(nodes['explorer']))
        with open(path) as f:
            text = f.read()
        write_config(directory, text.replace('process: own', 'process: alone'))
        _, status, errors, _ = launch_file(path)
        self.assertNotEqual(status, 0)
        self.assertIn("process", errors)
        self.assertIn("'alone'", errors)

    def test_a_planner_named_on_the_command_line_replaces_the_configured_one(self):
        config, _ = load_graph(os.path.join(ROOT, 'config', 'experiment.yaml'), '--planner',
                               'optimistic=ppp_agents/simple_planner.py', '--planner', 'ompl=')
        robots = sorted((n.namespace, role(n)) for n in config.nodes if n.namespace.endswith('/robot/'))
        self.assertEqual(robots, sorted(
            [(ns + 'robot/', 'dwa_planner_node') for name in ('dwa', 'dwa_continuous')
             for ns in instance_namespaces(name, CORES)] +
            [(ns + 'robot/', 'mrpt_planner_node') for ns in instance_namespaces('mrpt', CORES)] +
            [(ns + 'robot/', 'mrpt_reactive_node') for name in ('mrpt_nd', 'mrpt_nd_continuous')
             for ns in instance_namespaces(name, CORES)] +
            [(ns + 'robot/', 'mrpt_tpspace_node') for ns in instance_namespaces('mrpt_tpspace', CORES)] +
            [(ns + 'robot/', 'simple_planner.py') for ns in instance_namespaces('optimistic', CORES)]))
        # A planner of the user's runs as a process of its own; its bridge joins the manager.
        simple = [n for n in config.nodes if n.namespace.endswith('/robot/') and role(n) == 'simple_planner.py']
        self.assertEqual(set((n.package, nodelet_of(n)) for n in simple), {('ppp_agents', None)})
        bridges = [n for n in config.nodes if n.namespace.startswith('/optimistic/') and n.name == 'bridge']
        self.assertEqual(set(nodelet_of(n) for n in bridges), {'ppp_agents/PlannerBridge'})

    def test_your_own_planner_gets_a_bridge_and_optionally_its_node(self):
        config_path = os.path.join(ROOT, 'config', 'planner_experiment.yaml')
        bridge_only, _ = load_graph(config_path)
        mine = [(n.namespace, n.name, role(n)) for n in bridge_only.nodes if n.namespace.startswith('/mine/')]
        self.assertEqual(mine, [('/mine/', 'bridge', 'planner_bridge_node')])
        # A planner started by hand listens on the global /tf: its bridge broadcasts there.
        bridge = [n for n in bridge_only.nodes if n.namespace == '/mine/'][0]
        self.assertEqual(bridge.remap_args, [])
        started, _ = load_graph(config_path, '--planner', 'mine=ppp_agents/simple_planner.py')
        planner = sorted((n.namespace, n.name, n.package, n.type) for n in started.nodes if n.namespace.endswith('/robot/'))
        self.assertEqual(planner, [(ns + 'robot/', 'planner', 'ppp_agents', 'simple_planner.py')
                                   for ns in instance_namespaces('mine', CORES)])
        # The bridge waits five minutes for a planner started by hand, and joins the simulator only then: the
        # simulator waits for it as long, so a late planner costs no run. One the graph starts has 20 s, well
        # within the simulator's own default of 60 s.
        self.assertEqual(bridge_only.params['/mine/bridge/connect_timeout'].value, 300.0)
        self.assertEqual(bridge_only.params['/simulator/connect_timeout'].value, 310.0)
        for ns in instance_namespaces('mine', CORES):
            self.assertEqual(started.params[ns + 'bridge/connect_timeout'].value, 20.0)
        self.assertEqual(started.params['/simulator/connect_timeout'].value, 60.0)
        # The simulator reads the config file, which names no planner node: it is told the one given at launch,
        # so that it plays the instances the graph starts (one per core) rather than one.
        self.assertEqual(started.params['/simulator/planners'].value, ['mine=ppp_agents/simple_planner.py'])
        self.assertEqual(bridge_only.params['/simulator/planners'].value, [])


class SmallGraphTest(unittest.TestCase):
    def test_only_the_configs_own_nodes_on_the_hosts_it_names(self):
        directory = tempfile.mkdtemp()
        path = write_config(directory, small_config('memory: 5x5, host: 10.0.0.2'))
        config, _ = load_graph(path, '--env-loader', '/ws/devel/env.sh')
        self.assertEqual(sorted((role(n), n.name) for n in config.nodes if n.name != 'nodelet_manager'),
                         [('agent_node', 'astar'), ('agent_node', 'explorer'), ('generator_node', 'gen_mine'),
                          ('simulator_node', 'simulator')])
        explorer = [n for n in config.nodes if n.name == 'explorer'][0]
        machine = config.machines[explorer.machine_name]
        self.assertEqual((machine.address, machine.env_loader), ('10.0.0.2', '/ws/devel/env.sh'))
        # roslaunch's own 10 s for the remote roslaunch to register is too short on a busy host.
        self.assertEqual(machine.timeout, 60.0)
        self.assertIsNone([n for n in config.nodes if n.name == 'astar'][0].machine_name)
        self.assertEqual(config.params['/explorer/memory'].value, '5x5')
        text, _, _, _ = launch_file(path, '--env-loader', '/ws/devel/env.sh', '--json')
        self.assertEqual(json.loads(text)['machines'], [{'name': explorer.machine_name, 'address': '10.0.0.2',
                                                         'env_loader': '/ws/devel/env.sh', 'agents': ['explorer']}])

    def test_a_planners_time_limits_reach_its_bridge_and_its_node(self):
        directory = tempfile.mkdtemp()
        path = write_config(directory, """
agents:
  - {name: fast, type: planner, prior_map: true, planner_node: ppp_agents/ompl_planner_node,
     planner_args: "_planning_time:=0.005 _planner:=RRTConnect", plan_timeout: 0.5, cells_per_ppp_cell: 4,
     plan_requests: on_blocked, instances: 3}
robot_radius: 1.5
sets:
  - name: mine
    generator: {fitness: advances, population: 6, matings: 50, seed: 4, start: [2, 2], goal: [17, 17]}
""")
        config, _ = load_graph(path)
        for k in (1, 2, 3):
            namespace = '/fast/instance_%d/' % k
            planner = [n for n in config.nodes if n.namespace == namespace + 'robot/'][0]
            self.assertEqual(nodelet_of(planner), 'ppp_agents/OmplPlanner')
            self.assertEqual(node_args(planner), '_planning_time:=0.005 _planner:=RRTConnect')
            self.assertEqual(config.params[namespace + 'bridge/plan_timeout'].value, 0.5)
            self.assertEqual(config.params[namespace + 'bridge/cells_per_ppp_cell'].value, 4)
            self.assertEqual(config.params[namespace + 'bridge/plan_requests'].value, 'on_blocked')
            self.assertEqual(config.params[namespace + 'bridge/robot_radius'].value, 1.5)
            self.assertEqual(config.params[namespace + 'bridge/name'].value, 'fast')
        self.assertEqual(len([n for n in config.nodes if role(n) == 'planner_bridge_node']), 3)

    def test_a_set_that_starts_from_another_waits_for_its_generator(self):
        directory = tempfile.mkdtemp()
        path = write_config(directory, """
agents:
  - {name: explorer, type: explorer}
sets:
  - name: turns
    generator: {fitness: turns, population: 6, matings: 50}
  - name: hunted
    generator: {fitness: failure, agents: [explorer], population: 6, matings: 50, initial_pool: turns}
""")
        config, out = load_graph(path)
        self.assertEqual(config.params['/gen_hunted/wait_for_set'].value, '/gen_turns/problem_set')
        self.assertEqual(yaml.safe_load(config.params['/gen_hunted/options'].value)['initial_pool'],
                         os.path.join(out, 'sets', 'turns'))
        self.assertEqual(config.params['/gen_turns/wait_for_set'].value, '')
        # A hunt alone evolves no other set to start from.
        _, status, errors, _ = launch_file(path, '--hunt', 'hunted')
        self.assertNotEqual(status, 0)
        self.assertIn("set 'hunted' starts from set 'turns', which a hunt alone does not evolve", errors)

    def test_bad_configs_and_flags_are_refused_naming_the_problem(self):
        directory = tempfile.mkdtemp()
        agents = "agents:\n  - {name: a, type: %s%s}\n"
        sets = "sets:\n  - name: s\n    generator: {fitness: turns, population: 4, matings: 5}\n"
        cases = [
            (agents % ('flier', '') + sets, [], "unknown agent type 'flier'"),
            (agents % ('astar', ', host: "bad host"') + sets, [], 'host'),
            (agents % ('astar', ', host: 10.0.0.9') + sets, [], 'env_loader'),
            (agents % ('astar', ', planner_node: pkg/exe') + sets, [], 'planner_node: only planner agents'),
            (agents % ('planner', ', planner_node: nopackage') + sets, [], 'expected package/executable'),
            (agents % ('planner', ', planner_args: _a:=1') + sets, [], 'planner_args: given to the planner_node'),
            (agents % ('planner', ', planner_node: p/t, planner_args: "a:=1"') + sets, [],
             "expected private parameters _name:=value separated by spaces (e.g. _planning_time:=0.005), got 'a:=1'"),
            (agents % ('planner', ', plan_timeout: 0') + sets, [], 'plan_timeout: expected a number in [0.001, 86400]'),
            (agents % ('planner', ', lockstep: false, plan_requests: on_change') + sets, [],
             'plan_requests: a free-running bridge (lockstep: false) asks only when'),
            (agents % ('planner', '') + sets, ['--planner', 'other=p/t'], "no planner agent named 'other'"),
            (agents % ('planner', '') + sets, ['--planner', 'a'], 'expected NAME=PACKAGE/EXECUTABLE'),
        ]
        for text, flags, expected in cases:
            xml, status, errors, _ = launch_file(write_config(directory, text), *flags)
            self.assertNotEqual(status, 0, text)
            self.assertEqual(xml, '', text)
            self.assertIn(expected, errors, text)


class ContinuousGraphTest(unittest.TestCase):
    SETS = "sets:\n  - name: s\n    generator: {fitness: turns, population: 4, matings: 5}\n"

    def test_astar_in_continuous_motion_runs_one_agent_node_per_core(self):
        path = write_config(tempfile.mkdtemp(), "motion: continuous\nagents:\n  - {name: astar, type: astar}\n"
                            "  - {name: explorer, type: explorer, motion: grid}\n" + self.SETS)
        graph, _ = load_graph(path)
        agent_nodes = sorted(n.namespace + n.name for n in graph.nodes if role(n) == 'agent_node')
        self.assertEqual(agent_nodes, sorted([ns.rstrip('/') for ns in instance_namespaces('astar', CORES)] +
                                             ['/explorer']))
        for node in graph.nodes:
            remaps = [list(r) for r in node.remap_args]
            if role(node) == 'agent_node' and node.namespace.startswith('/astar'):
                self.assertIn(['sensing', '~sensing'], remaps)
                self.assertIn(['commands', '~commands'], remaps)
            # No planner: every node keeps the system's time, and nothing sets /use_sim_time.
            self.assertNotIn('/use_sim_time', [r[0] for r in remaps])
        self.assertNotIn('/use_sim_time', graph.params)

    def test_a_planner_in_continuous_motion_runs_on_its_bridges_clock(self):
        path = write_config(tempfile.mkdtemp(), "motion: continuous\nagents:\n  - {name: astar, type: astar}\n"
                            "  - {name: steer, type: planner, interface: cmd_vel, instances: 2, "
                            "planner_node: ppp_agents/steering_planner.py}\n" + self.SETS)
        graph, _ = load_graph(path)
        self.assertIs(graph.params['/use_sim_time'].value, True)
        planners = [n for n in graph.nodes if n.namespace.endswith('/robot/')]
        self.assertEqual(sorted(n.namespace for n in planners),
                         [ns + 'robot/' for ns in instance_namespaces('steer', 2)])
        for node in graph.nodes:
            remaps = [list(r) for r in node.remap_args]
            if node in planners:
                # A process of its own (a process has one time), on the clock its bridge publishes.
                self.assertIsNone(nodelet_of(node))
                self.assertIn(['/clock', node.namespace + 'clock'], remaps)
                self.assertNotIn('/use_sim_time', [r[0] for r in remaps])
                # It is told the robot it drives.
                self.assertEqual(graph.params[node.namespace + node.name + '/kinematics'].value, 'diff_drive')
            else:
                self.assertIn(['/use_sim_time', '/ppp/use_system_time'], remaps, node.namespace + node.name)

    def test_each_bridge_is_told_what_wakes_its_planner(self):
        # auto: this repository's local planners answer their messages, any other planner a timer; a value given
        # in the config stands.
        path = write_config(tempfile.mkdtemp(), "motion: continuous\nagents:\n"
                            "  - {name: dwa, type: planner, interface: cmd_vel, instances: 1, "
                            "planner_node: ppp_agents/dwa_planner_node}\n"
                            "  - {name: tp, type: planner, interface: cmd_vel, instances: 1, "
                            "planner_node: ppp_agents/mrpt_tpspace_node}\n"
                            "  - {name: steer, type: planner, interface: cmd_vel, instances: 1, "
                            "planner_node: ppp_agents/steering_planner.py}\n"
                            "  - {name: mine, type: planner, interface: cmd_vel}\n"
                            "  - {name: told, type: planner, interface: cmd_vel, instances: 1, wakes_on: timer, "
                            "planner_node: ppp_agents/mrpt_reactive_node}\n" + self.SETS)
        graph, _ = load_graph(path)
        woken = {name: graph.params['/%s/bridge/wakes_on' % name].value
                 for name in ('dwa', 'tp', 'steer', 'mine', 'told')}
        self.assertEqual(woken, {'dwa': 'messages', 'tp': 'messages', 'steer': 'timer', 'mine': 'timer',
                                 'told': 'timer'})
        # And which messages each period sends it: only what changed to this repository's planners that answer
        # their messages, the map and goal with every period to any other.
        sent = {name: graph.params['/%s/bridge/period_messages' % name].value
                for name in ('dwa', 'tp', 'steer', 'mine', 'told')}
        self.assertEqual(sent, {'dwa': 'changes', 'tp': 'changes', 'steer': 'every', 'mine': 'every',
                                'told': 'every'})

    def assert_refused(self, agent, message):
        """A continuous experiment with the one agent entry `agent` gives no graph and an error saying `message`."""
        path = write_config(tempfile.mkdtemp(), "motion: continuous\nagents:\n  - %s\n" % agent + self.SETS)
        xml, status, errors, _ = launch_file(path)
        self.assertNotEqual(status, 0)
        self.assertEqual(xml, '')
        self.assertIn(message, errors)

    def test_only_changes_for_a_planner_woken_by_a_timer_is_refused_naming_period_messages(self):
        self.assert_refused("{name: steer, type: planner, interface: cmd_vel, period_messages: changes, "
                            "planner_node: ppp_agents/steering_planner.py}",
                            "period_messages: changes needs a planner that answers each period's messages "
                            "(wakes_on: messages)")

    def test_a_free_running_planner_in_continuous_motion_is_refused_naming_lockstep(self):
        self.assert_refused("{name: ompl, type: planner, lockstep: false, planner_node: ppp_agents/ompl_planner_node}",
                            "lockstep: planner agent 'ompl' plays in continuous motion, which its bridge plays in "
                            "lockstep only")


class InspectLaunchTest(unittest.TestCase):
    def test_rviz_alone_or_with_a_bag(self):
        config = load('inspect.launch')
        self.assertEqual([(n.package, n.type) for n in config.nodes], [('rviz', 'rviz')])
        self.assertEqual(os.path.normpath(config.nodes[0].args.split()[-1]), os.path.join(ROOT, 'launch', 'ppp.rviz'))
        config = load('inspect.launch', 'bag:=/data/x.bag')
        players = [n for n in config.nodes if n.package == 'rosbag']
        self.assertEqual(len(players), 1)
        self.assertIn('--clock', players[0].args)
        self.assertIn('/data/x.bag', players[0].args)
        self.assertIs(config.params['/use_sim_time'].value, True)

    def test_rviz_shows_each_shipped_agent_in_continuous_motion_with_its_heading(self):
        with open(os.path.join(ROOT, 'config', 'agents.yaml')) as f:
            driven = [a['name'] for a in yaml.safe_load(f)['agents'] if a.get('motion') == 'continuous']
        self.assertGreaterEqual(len(driven), 2)
        with open(os.path.join(ROOT, 'launch', 'ppp.rviz')) as f:
            displays = yaml.safe_load(f)['Visualization Manager']['Displays']
        paths = {d['Topic']: d for d in displays if d['Class'] == 'rviz/Path'}
        for name in driven:
            # Its recorded path's poses, each an arrow along the robot's heading.
            self.assertEqual(paths['/' + name + '/path']['Pose Style'], 'Arrows', name)


class HuntLaunchTest(unittest.TestCase):
    def test_the_entry_runs_the_launcher_for_one_set(self):
        config = load('hunt.launch', 'output_dir:=relative/hunt', 'set:=mine')
        self.assertEqual([(n.type, n.name, n.required) for n in config.nodes], [('experiment_launcher', 'hunt', True)])
        args = config.nodes[0].args.split()
        self.assertEqual(args[args.index('--hunt') + 1], "'mine'")
        self.assertEqual(args[args.index('--output-dir') + 1], "'%s'" % os.path.join(os.getcwd(), 'relative', 'hunt'))

    def test_the_hunt_graph_starts_the_hunter_the_simulator_and_the_panel_only(self):
        config, out = load_graph(os.path.join(ROOT, 'config', 'experiment.yaml'), '--hunt', 'hunted')
        params = {k: p.value for k, p in config.params.items()}
        self.assertEqual(sorted((role(n), n.name) for n in config.nodes if n.name != 'nodelet_manager'),
                         [('agent_node', 'bumper'), ('agent_node', 'explorer'), ('agent_node', 'wall_follower_left'),
                          ('generator_node', 'gen_hunted'), ('simulator_node', 'simulator')])
        # The hunt's generator ends the graph: its nodelet shuts the (required) manager down once the set is out.
        self.assertEqual([n.name for n in config.nodes if n.required], ['nodelet_manager'])
        self.assertEqual(nodelet_of([n for n in config.nodes if n.name == 'gen_hunted'][0]), 'ppp_generator/Generator')
        self.assertEqual(params['/simulator/mode'], 'hunt')
        self.assertIs(params['/gen_hunted/exit_when_done'], True)
        self.assertEqual(params['/gen_hunted/output_dir'], out)
        self.assertEqual(yaml.safe_load(params['/gen_hunted/options'])['agents'],
                         ['wall_follower_left', 'explorer', 'bumper'])

    def test_a_planner_hunt_starts_its_bridge_and_planner_only(self):
        config, _ = load_graph(os.path.join(ROOT, 'config', 'planner_hunt.yaml'), '--hunt', 'hunted_mine',
                               '--planner', 'mine=ppp_agents/simple_planner.py')
        started = sorted((n.namespace, n.name, role(n)) for n in config.nodes if n.namespace.startswith('/mine/'))
        self.assertEqual(started, sorted([(ns, 'bridge', 'planner_bridge_node') for ns in instance_namespaces('mine', CORES)] +
                                         [(ns + 'robot/', 'planner', 'simple_planner.py')
                                          for ns in instance_namespaces('mine', CORES)]))
        self.assertEqual([n for n in config.nodes if role(n) == 'agent_node'], [])

    def test_only_failure_sets_can_be_hunted(self):
        _, status, errors, _ = launch_file(os.path.join(ROOT, 'config', 'experiment.yaml'), '--hunt', 'turns')
        self.assertNotEqual(status, 0)
        self.assertIn("no set 'turns' evolved with a panel fitness (its hunted sets: hunted)", errors)


class ShrinkLaunchTest(unittest.TestCase):
    def test_the_entry_runs_the_launcher_with_the_shrink_flags_and_absolute_paths(self):
        config = load('shrink.launch', 'input:=relative/ppp_011.ppp', 'agent:=mrpt', 'output:=small.ppp',
                      'results:=run/results.csv', 'args:=--runs 2')
        self.assertEqual([(n.type, n.name, n.required) for n in config.nodes],
                         [('experiment_launcher', 'shrink_launch', True)])
        args = shlex.split(config.nodes[0].args)
        self.assertEqual(args[args.index('--output-dir') + 1], os.path.join(os.getcwd(), 'small.ppp'))
        flags = shlex.split(next(a for a in args if a.startswith('--args='))[len('--args='):])
        value = lambda flag: flags[flags.index(flag) + 1]
        self.assertEqual(value('--shrink'), os.path.join(os.getcwd(), 'relative', 'ppp_011.ppp'))
        self.assertEqual(value('--agent'), 'mrpt')
        self.assertEqual(value('--results'), os.path.join(os.getcwd(), 'run', 'results.csv'))
        self.assertEqual(value('--runs'), '2')

    def test_the_shrink_graph_starts_the_shrink_node_the_simulator_and_the_agent_only(self):
        ppp = os.path.join(ROOT, 'ppp_simulator', 'test', 'ros', 'planner_maps', 'wall.ppp')
        config, out = load_graph(os.path.join(ROOT, 'config', 'experiment.yaml'), '--shrink', ppp, '--agent', 'mrpt',
                                 '--seed', '16126441926964728741', '--runs', '3')
        params = {k: p.value for k, p in config.params.items()}
        self.assertEqual(sorted((n.namespace, n.name, role(n)) for n in config.nodes),
                         sorted([('/', 'shrink', 'shrink_node'), ('/', 'simulator', 'simulator_node'),
                                 ('/', 'nodelet_manager', 'nodelet')] +
                                [(ns, 'bridge', 'planner_bridge_node') for ns in instance_namespaces('mrpt', CORES)] +
                                [(ns + 'robot/', 'planner', 'mrpt_planner_node')
                                 for ns in instance_namespaces('mrpt', CORES)]))
        self.assertTrue([n for n in config.nodes if n.name == 'shrink'][0].required)
        self.assertFalse([n for n in config.nodes if n.name == 'simulator'][0].required)
        self.assertEqual(params['/simulator/mode'], 'hunt')
        self.assertEqual((params['/shrink/input'], params['/shrink/agent'], params['/shrink/output']), (ppp, 'mrpt', out))
        self.assertEqual(params['/shrink/config'], os.path.join(ROOT, 'config', 'experiment.yaml'))
        # A 64-bit seed is beyond an XML-RPC integer: it travels as text and is read back whole.
        self.assertEqual(params['/shrink/seed'], '16126441926964728741')
        self.assertEqual(params['/shrink/runs'], 3)

    def test_bad_shrinks_are_refused_naming_the_flag(self):
        ppp = os.path.join(ROOT, 'ppp_simulator', 'test', 'ros', 'planner_maps', 'wall.ppp')
        config = os.path.join(ROOT, 'config', 'experiment.yaml')
        for flags, error in ((['--shrink', ppp, '--agent', 'nobody'], "--agent: the config has no agent 'nobody'"),
                             (['--shrink', '/no/such.ppp', '--agent', 'mrpt'], "--shrink: '/no/such.ppp' does not exist"),
                             (['--agent', 'mrpt'], '--agent: only a shrink takes it: give --shrink INPUT too'),
                             (['--shrink', ppp, '--agent', 'mrpt', '--runs', '-1'],
                              '--runs: expected an integer in [0, 100000], got -1'),
                             (['--shrink', ppp, '--agent', 'mrpt', '--min-rate', '2'],
                              '--min-rate: expected a number in [0, 1], got 2')):
            _, status, errors, _ = launch_file(config, *flags)
            self.assertNotEqual(status, 0, flags)
            self.assertIn(error, errors, flags)


class CheckLaunchTest(unittest.TestCase):
    def test_the_entry_runs_the_launcher_with_the_check_flags_and_absolute_paths(self):
        config = load('check.launch', 'corpus:=relative/corpus', 'agent:=mrpt', 'junit:=out/check.xml',
                      'args:=--runs 2')
        self.assertEqual([(n.type, n.name, n.required) for n in config.nodes],
                         [('experiment_launcher', 'check_launch', True)])
        args = shlex.split(config.nodes[0].args)
        flags = shlex.split(next(a for a in args if a.startswith('--args='))[len('--args='):])
        value = lambda flag: flags[flags.index(flag) + 1]
        self.assertEqual(value('--check'), os.path.join(os.getcwd(), 'relative', 'corpus'))
        self.assertEqual(value('--agent'), 'mrpt')
        self.assertEqual(value('--junit'), os.path.join(os.getcwd(), 'out', 'check.xml'))
        self.assertEqual(value('--runs'), '2')

    def test_the_check_graph_starts_the_check_node_the_simulator_and_the_agent_only(self):
        corpus = os.path.join(ROOT, 'ppp_simulator', 'test', 'ros', 'planner_maps')
        config, _ = load_graph(os.path.join(ROOT, 'config', 'experiment.yaml'), '--check', corpus, '--agent', 'mrpt',
                               '--seed', '16126441926964728741', '--runs', '2', '--junit', '/tmp/check.xml')
        params = {k: p.value for k, p in config.params.items()}
        self.assertEqual(sorted((n.namespace, n.name, role(n)) for n in config.nodes),
                         sorted([('/', 'check', 'check_node'), ('/', 'simulator', 'simulator_node'),
                                 ('/', 'nodelet_manager', 'nodelet')] +
                                [(ns, 'bridge', 'planner_bridge_node') for ns in instance_namespaces('mrpt', CORES)] +
                                [(ns + 'robot/', 'planner', 'mrpt_planner_node')
                                 for ns in instance_namespaces('mrpt', CORES)]))
        self.assertTrue([n for n in config.nodes if n.name == 'check'][0].required)
        self.assertFalse([n for n in config.nodes if n.name == 'simulator'][0].required)
        self.assertEqual(params['/simulator/mode'], 'hunt')
        self.assertEqual((params['/check/corpus'], params['/check/agent'], params['/check/junit']),
                         (corpus, 'mrpt', '/tmp/check.xml'))
        self.assertEqual(params['/check/seed'], '16126441926964728741')
        self.assertEqual(params['/check/runs'], 2)

    def test_bad_checks_are_refused_naming_the_flag(self):
        corpus = os.path.join(ROOT, 'ppp_simulator', 'test', 'ros', 'planner_maps')
        config = os.path.join(ROOT, 'config', 'experiment.yaml')
        for flags, error in ((['--check', corpus, '--agent', 'nobody'], "--agent: the config has no agent 'nobody'"),
                             (['--check', corpus], '--agent: required'),
                             (['--check', corpus, '--agent', 'mrpt', '--runs', '0'],
                              '--runs: expected an integer in [1, 100000], got 0'),
                             (['--check', corpus, '--agent', 'mrpt', '--by', 'cells'],
                              '--by: only a shrink takes it, not a check'),
                             (['--check', corpus, '--shrink', corpus, '--agent', 'mrpt'],
                              '--check: a graph checks or shrinks, not both'),
                             (['--junit', '/tmp/check.xml'], '--junit: only a check takes it: give --check')):
            _, status, errors, _ = launch_file(config, *flags)
            self.assertNotEqual(status, 0, flags)
            self.assertIn(error, errors, flags)


if __name__ == '__main__':
    unittest.main()
