#!/usr/bin/env python3
"""bench/relief_distance.py's crease sharpness and its 8-bit floor on synthetic screenshots: a
smooth fold of a few grey levels, rounded to 8 bits as rviz's screenshots are, measures near the
floor screenshot_floor() gives it (far above (2 pi / period)^2, which ignores the rounding), and a
creased fold (a square wave) of the same period and strength measures far above that floor.

Usage: test_crease_sharpness.py <repository root>
"""
import os
import sys
import unittest

import numpy

ROOT = os.path.abspath(sys.argv[1]) if len(sys.argv) > 1 else "."
sys.argv[1:] = sys.argv[2:]
sys.path.insert(0, os.path.join(ROOT, "bench"))
import relief_distance as rd  # noqa: E402

PERIOD = 25.0  # px, the folds' period at 2.5 m in docs/relief_distance.md


def shots(wave, amplitude):
    """A flat garment with smooth shading and the same with a fold pattern, both rounded to 8 bits;
    the luminance change, the garment mask and the flat shot."""
    y, x = numpy.mgrid[0:300, 0:400].astype(float)
    shade = 110.0 + 40.0 * numpy.sin(x / 97.0) + 30.0 * numpy.cos(y / 131.0)
    flat = numpy.round(shade[:, :, None] * numpy.array([0.9, 0.95, 1.4])[None, None, :])
    garment = numpy.zeros(shade.shape, dtype=bool)
    garment[20:280, 30:370] = True
    fold = amplitude * wave(2.0 * numpy.pi * (x * numpy.cos(0.5) + y * numpy.sin(0.5)) / PERIOD)
    luminance = flat @ rd.LUMINANCE
    relief = numpy.clip(numpy.round(flat + (fold / luminance)[:, :, None] * flat), 0.0, 255.0)
    change = numpy.where(garment, (relief - flat) @ rd.LUMINANCE, 0.0)
    return change, garment, flat


class CreaseSharpness(unittest.TestCase):
    def measured(self, wave, amplitude):
        change, garment, flat = shots(wave, amplitude)
        sharpness, shown = rd.crease_sharpness(change, garment)
        frequency = rd.fold_frequency(change, shown)
        self.assertAlmostEqual(1.0 / numpy.hypot(*frequency), PERIOD, delta=1.0)
        return sharpness, rd.screenshot_floor(flat, change, shown, garment, frequency)

    def test_a_smooth_fold_measures_near_its_floor(self):
        for amplitude in (4.0, 10.0):
            sharpness, floor = self.measured(numpy.sin, amplitude)
            self.assertGreater(floor, 1.5 * (2.0 * numpy.pi / PERIOD) ** 2, amplitude)  # the rounding shows
            self.assertLess(sharpness, 1.35 * floor, amplitude)
            self.assertGreater(sharpness, 0.8 * floor, amplitude)

    def test_a_creased_fold_measures_far_above_its_floor(self):
        for amplitude in (4.0, 10.0):
            sharpness, floor = self.measured(lambda t: numpy.sign(numpy.sin(t)), amplitude)
            self.assertGreater(sharpness, 2.5 * floor, amplitude)


if __name__ == "__main__":
    unittest.main()
