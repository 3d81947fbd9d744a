#!/usr/bin/python3
"""The shipped launch files agree with the shipped configuration.

launch/experiment.launch must start one agent node per entry of config/agents.yaml (node name = the agent's
ROS name, ~type/~memory/~sensor_noise as in the file, topics /NAME/scans and /NAME/moves), one generator node
per set of config/experiment.yaml with that set's options, and the simulator waiting for their sets.
launch/inspect.launch must load with and without a bag. launch/hunt.launch must start the simulator in hunt mode,
the hunter with the failure fitness and the panel, the same agent nodes, and a planner's bridge when asked. Loads the files with roslaunch's own parser; starts
nothing. Usage: launch_files_test.py REPOSITORY_ROOT
"""
import os
import re
import sys
import unittest

import roslaunch.config
import yaml

ROOT = os.path.abspath(sys.argv.pop(1) if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), '..', '..'))


def graph_name(name):
    """ppp::agents::agentGraphName: the agent name as a legal ROS name."""
    prefixed = name if re.match('[A-Za-z]', name) else 'agent_' + name
    return re.sub('[^A-Za-z0-9_]', '_', prefixed)


def load(launch, *args):
    # The launch files resolve relative paths against $PWD, as a shell keeps it; ctest changes directory without.
    os.environ['PWD'] = os.getcwd()
    path = os.path.join(ROOT, 'launch', launch)
    return roslaunch.config.load_config_default([(path, list(args))], None, assign_machines=False)


class ExperimentLaunchTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.config = load('experiment.launch', 'output_dir:=relative/out')
        cls.nodes = {n.name: n for n in cls.config.nodes}
        cls.params = {k: p.value for k, p in cls.config.params.items()}
        with open(os.path.join(ROOT, 'config', 'experiment.yaml')) as f:
            cls.experiment = yaml.safe_load(f)
        with open(os.path.join(ROOT, 'config', cls.experiment['agents'])) as f:
            cls.agents = yaml.safe_load(f)['agents']

    def test_one_agent_node_per_configured_agent(self):
        built_in = [a for a in self.agents if a['type'] != 'planner']
        agent_nodes = sorted(n.name for n in self.config.nodes if n.type == 'agent_node')
        self.assertEqual(agent_nodes, sorted(graph_name(a['name']) for a in built_in))
        for agent in built_in:
            node_name = graph_name(agent['name'])
            node = self.nodes[node_name]
            self.assertEqual(node.package, 'ppp_agents')
            self.assertEqual(node.namespace, '/')
            self.assertEqual(node.machine_name, 'local')
            self.assertIn(['scans', '~scans'], [list(r) for r in node.remap_args])
            self.assertIn(['moves', '~moves'], [list(r) for r in node.remap_args])
            prefix = '/%s/' % node_name
            self.assertEqual(self.params[prefix + 'type'], agent['type'], node_name)
            self.assertEqual(self.params[prefix + 'memory'], agent.get('memory', 'full'), node_name)
            self.assertEqual(self.params[prefix + 'sensor_noise'], agent.get('sensor_noise', 0.0), node_name)
            self.assertEqual(self.params.get(prefix + 'name', node_name), agent['name'], node_name)

    def test_one_bridge_and_one_planner_per_planner_agent(self):
        planners = [a for a in self.agents if a['type'] == 'planner']
        self.assertEqual(len(planners), 2)
        bridges = sorted(n.namespace for n in self.config.nodes if n.type == 'planner_bridge_node')
        self.assertEqual(bridges, sorted('/%s/' % graph_name(a['name']) for a in planners))
        for agent in planners:
            namespace = '/%s/' % graph_name(agent['name'])
            bridge = [n for n in self.config.nodes if n.type == 'planner_bridge_node' and n.namespace == namespace][0]
            self.assertEqual(bridge.name, 'bridge')
            self.assertEqual(self.params.get(namespace + 'bridge/memory', 'full'), agent.get('memory', 'full'))
            planner_nodes = [n for n in self.config.nodes if n.namespace == namespace + 'robot/']
            self.assertEqual(len(planner_nodes), 1, namespace)
            self.assertEqual(planner_nodes[0].package, 'ppp_agents')

    def test_your_own_planner_gets_a_bridge_and_optionally_its_node(self):
        bridge_only = load('experiment.launch', 'output_dir:=out', 'planner:=mine')
        mine = [n for n in bridge_only.nodes if n.namespace.startswith('/mine/')]
        self.assertEqual([(n.namespace, n.name, n.type) for n in mine], [('/mine/', 'bridge', 'planner_bridge_node')])
        started = load('experiment.launch', 'output_dir:=out', 'planner:=mine', 'planner_pkg:=ppp_agents',
                       'planner_type:=simple_planner.py')
        planner = [n for n in started.nodes if n.namespace == '/mine/robot/']
        self.assertEqual([(n.name, n.package, n.type) for n in planner], [('planner', 'ppp_agents', 'simple_planner.py')])
        with open(os.path.join(ROOT, 'config', 'planner_experiment.yaml')) as f:
            experiment = yaml.safe_load(f)
        self.assertIn({'name': 'mine', 'type': 'planner'}, experiment['agents'])
        self.assertEqual(experiment['sets'], self.experiment['sets'])

    def test_generator_nodes_make_the_configured_sets(self):
        with open(os.path.join(ROOT, 'config', 'generator.yaml')) as f:
            defaults = yaml.safe_load(f)
        topics = []
        for s in self.experiment['sets']:
            node_name = 'gen_' + s['name']
            if s['generator']['fitness'] == 'failure':
                # A hunt plays episodes: the simulator node evolves it in process (no generator node).
                self.assertNotIn(node_name, self.nodes)
                continue
            self.assertIn(node_name, self.nodes)
            self.assertIn(['problem_set', '~problem_set'], [list(r) for r in self.nodes[node_name].remap_args])
            options = dict(defaults, **s['generator'])
            for key in ('fitness', 'seed', 'matings', 'population', 'width', 'height', 'max_obstacles'):
                self.assertEqual(self.params['/%s/%s' % (node_name, key)], options[key], node_name + ' ' + key)
            self.assertEqual(self.params['/%s/output_dir' % node_name],
                             os.path.join(os.getcwd(), 'relative', 'out', 'sets', s['name']))
            topics.append(node_name + '/problem_set')
        self.assertEqual(self.params['/simulator/wait_for_sets'], topics)

    def test_simulator_is_required_and_gets_absolute_paths(self):
        simulator = self.nodes['simulator']
        self.assertTrue(simulator.required)
        self.assertEqual(self.params['/simulator/output_dir'], os.path.join(os.getcwd(), 'relative', 'out'))
        self.assertTrue(os.path.isfile(self.params['/simulator/config']))
        self.assertEqual(self.params['/simulator/batch_size'], 2000)
        self.assertEqual(self.params['/simulator/step_timeout'], 5.0)
        self.assertIs(self.params['/simulator/record'], True)

    def test_arguments_reach_the_simulator_with_their_types(self):
        config = load('experiment.launch', 'output_dir:=/abs/out', 'step_timeout:=2', 'batch_size:=7',
                      'record:=false', 'agent_machine:=other')
        params = {k: p.value for k, p in config.params.items()}
        self.assertEqual(params['/simulator/output_dir'], '/abs/out')
        self.assertEqual(params['/simulator/step_timeout'], 2.0)
        self.assertIsInstance(params['/simulator/step_timeout'], float)
        self.assertEqual(params['/simulator/batch_size'], 7)
        self.assertIs(params['/simulator/record'], False)
        self.assertEqual({n.machine_name for n in config.nodes if n.type == 'agent_node'}, {'other'})


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


class HuntLaunchTest(unittest.TestCase):
    def test_hunt_starts_the_simulator_in_hunt_mode_and_the_hunter_with_the_panel(self):
        config = load('hunt.launch', 'output_dir:=relative/hunt', 'agents:=wall_follower_left,explorer_noise_0.1',
                      'matings:=77')
        nodes = {n.name: n for n in config.nodes}
        params = {k: p.value for k, p in config.params.items()}
        self.assertTrue(nodes['simulator'].required)
        self.assertTrue(nodes['hunter'].required)
        self.assertEqual(params['/simulator/mode'], 'hunt')
        self.assertTrue(os.path.isfile(params['/simulator/config']))
        self.assertEqual(params['/hunter/fitness'], 'failure')
        self.assertEqual(params['/hunter/agents'], ['wall_follower_left', 'explorer_noise_0.1'])
        self.assertEqual(params['/hunter/matings'], 77)
        self.assertEqual(params['/hunter/crowding_window'], 4)
        self.assertEqual(params['/hunter/evaluator'], '/simulator/evaluate')
        self.assertTrue(params['/hunter/exit_when_done'])
        self.assertEqual(params['/hunter/output_dir'], os.path.join(os.getcwd(), 'relative', 'hunt'))
        self.assertEqual(len([n for n in config.nodes if n.type == 'agent_node']), 10)
        self.assertEqual([n for n in config.nodes if n.type == 'planner_bridge_node'], [])

    def test_a_planner_hunt_starts_its_bridge_and_planner_only(self):
        config = load('hunt.launch', 'output_dir:=/tmp/h', 'agents:=mine', 'planner:=mine', 'built_in_agents:=false',
                      'planner_pkg:=ppp_agents', 'planner_type:=simple_planner.py')
        self.assertEqual([n for n in config.nodes if n.type == 'agent_node'], [])
        started = sorted((n.namespace, n.name, n.type) for n in config.nodes if n.namespace.startswith('/mine/'))
        self.assertEqual(started, [('/mine/', 'bridge', 'planner_bridge_node'),
                                   ('/mine/robot/', 'planner', 'simple_planner.py')])


if __name__ == '__main__':
    unittest.main()
