#!/usr/bin/python3
"""The DressedHuman display draws the human where the camera looks, with visible relief, and
reports no error."""
import os
import tempfile
import unittest

import numpy
import rospy
import rostest

from screenshots import Rviz, figure_mask, high_pass_energy, wait_for_figure


class DisplayScreenshotTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_display_screenshot")
        cls.directory = tempfile.mkdtemp()
        cls.images, cls.outputs = {}, {}
        for mode in ("Bump mapping", "Flat"):
            path = os.path.join(cls.directory, mode.replace(" ", "_") + ".png")
            with Rviz("display_test.rviz", {"RELIEF_MODE": mode}) as rviz:
                cls.images[mode] = wait_for_figure(rviz, path)
                cls.outputs[mode] = rviz.output()
            rospy.loginfo("screenshot %s: %s", mode, path)

    def test_human_covers_the_centre_of_the_view(self):
        mask = figure_mask(self.images["Bump mapping"])
        rows, columns = numpy.nonzero(mask)
        rospy.loginfo("figure: %d pixels, rows %d..%d, columns %d..%d", mask.sum(), rows.min(), rows.max(),
                      columns.min(), columns.max())
        self.assertGreater(mask.sum(), 20000)
        self.assertLess(mask.sum(), 0.5 * mask.size)
        # The figure stands in the middle of the 3D view and is taller than wide.
        self.assertLess(abs(columns.mean() - mask.shape[1] / 2), mask.shape[1] / 8)
        self.assertGreater(rows.max() - rows.min(), 1.5 * (numpy.percentile(columns, 95) - numpy.percentile(columns, 5)))

    def test_skin_colour(self):
        image = self.images["Flat"]
        mean = image[figure_mask(image)].mean(axis=0)
        rospy.loginfo("mean figure colour (flat): %s", mean)
        self.assertGreater(mean[0], mean[1])  # skin: red > green > blue
        self.assertGreater(mean[1], mean[2])

    def test_relief_is_visible(self):
        bump, bump_pixels = high_pass_energy(self.images["Bump mapping"], figure_mask(self.images["Bump mapping"]))
        flat, flat_pixels = high_pass_energy(self.images["Flat"], figure_mask(self.images["Flat"]))
        rospy.loginfo("high-pass luminance energy: bump %.3f over %d px, flat %.3f over %d px",
                      bump, bump_pixels, flat, flat_pixels)
        self.assertGreater(bump, 1.5 * flat)

    def test_no_error_reported(self):
        for mode, output in self.outputs.items():
            errors = [line for line in output.splitlines() if "ERROR" in line and "dressed_human" in line.lower()]
            self.assertEqual(errors, [], "%s: %s" % (mode, errors))


if __name__ == "__main__":
    rostest.rosrun("dressed_human", "display_screenshot", DisplayScreenshotTest)
