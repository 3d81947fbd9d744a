#!/usr/bin/python3
"""scripts/seed_spread.py's summary on hand-made rates, every expected figure worked out by hand."""
import os
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'scripts'))
from seed_spread import nearest_rank, summarize  # noqa: E402


class SummaryTest(unittest.TestCase):
    """Three seeds' rates of one referenced agent and one other."""

    def setUp(self):
        # agent a: 10, 20, 60 -> mean 30, sd sqrt((400 + 100 + 900) / 2) = 26.46; b has no reference.
        self.played = {1: {('s', 'a'): 10.0, ('s', 'b'): 5.0},
                       2: {('s', 'a'): 20.0, ('s', 'b'): 5.0},
                       3: {('s', 'a'): 60.0, ('s', 'b'): 8.0}}

    def test_rows(self):
        lines = summarize(self.played, {('s', 'a'): 25.0}, 10.0)
        # 5th and 95th percentile by nearest rank of three values: the 1st (ceil(0.15)) and the 3rd (ceil(2.85));
        # two of three below 25.
        self.assertIn('| s | a | 25.00 | 30.00 | 26.46 | 10.0 - 60.0 | 67 % |', lines)
        self.assertIn('| s | b |  | 6.00 | 1.73 | 5.0 - 8.0 |  |', lines)

    def test_typical_and_within(self):
        lines = summarize(self.played, {('s', 'a'): 25.0}, 10.0)
        # Distances from the mean 30: 20, 10, 30 -> seed 2; within 10 of 25: 20 only (10 and 60 are 15 and 35 off).
        self.assertIn('The most typical set: seed 2 (its rates 10.0 points from the mean over the seeds, root mean '
                      'square; blind to the reference)', lines)
        self.assertIn('Sets within 10 points of every reference: 1 of 3 (seeds 2)', lines)
        self.assertIn('The most typical of them: seed 2 (10.0 points from the mean)', lines)

    def test_within_is_every_reference(self):
        played = {1: {('s', 'a'): 30.0, ('s', 'b'): 50.0}, 2: {('s', 'a'): 26.0, ('s', 'b'): 90.0}}
        lines = summarize(played, {('s', 'a'): 25.0, ('s', 'b'): 85.0}, 5.0)
        # Seed 1: a within (5), b 35 off; seed 2: a 1 off, b 5 off (the boundary counts).
        self.assertIn('Sets within 5 points of every reference: 1 of 2 (seeds 2)', lines)

    def test_ties_count_half_despite_rounding(self):
        # 0.3219 read back and scaled is not the decimal 32.19; it is a tie all the same, as is the tolerance edge.
        played = {1: {('s', 'a'): 100 * 0.3219}, 2: {('s', 'a'): 40.01}}
        self.assertNotEqual(100 * 0.3219, 32.19)
        lines = summarize(played, {('s', 'a'): 32.19}, 7.82)
        # Mean 36.10, sd 7.82 / sqrt(2) = 5.53; one tie (half) of two: 25 %; seed 2 exactly 7.82 off.
        self.assertIn('| s | a | 32.19 | 36.10 | 5.53 | 32.2 - 40.0 | 25 % |', lines)
        self.assertIn('Sets within 7.82 points of every reference: 2 of 2 (seeds 1, 2)', lines)

    def test_nearest_rank(self):
        values = list(range(1, 201))  # 1 .. 200
        self.assertEqual(nearest_rank(values, 0.05), 10)  # ten values at or below it
        self.assertEqual(nearest_rank(values, 0.95), 190)
        self.assertEqual(nearest_rank([7.0], 0.05), 7.0)


if __name__ == '__main__':
    unittest.main()
