#!/usr/bin/python3
"""The DressedHuman display draws the human where the camera looks, with visible relief, and
reports no error."""
import os
import tempfile
import time
import unittest

import numpy
import rospy
import rostest

from screenshots import Rviz, figure_mask, high_pass_energy, package_errors, wait_for_figure


# GPU against CPU vertex evaluation (README, The rviz display, states these bounds). Both draw
# the same float surface; what may differ is rounding and the shader's approximate pole normals.
# Measured on Mesa llvmpipe, the human frozen bent (display_screenshot.test), 7 runs identical:
# garments mean 0.000 grey levels, largest 3; whole figure mean 0.001, largest 5; relief ratio
# 1.000. With the shader's wrinkle strength halved: garments mean 1.9, largest 112, relief ratio
# 0.53 (standing, the halved shader gave a whole-figure mean of 0.32: only the bent pose shows
# the wrinkle strength at full size).
MAX_MEAN_DIFFERENCE = 0.1       # grey levels, mean over the pixels compared
MAX_PIXEL_DIFFERENCE = 40       # grey levels, any one pixel (largest channel difference)
MAX_RELIEF_RATIO_OFF = 0.02     # the GPU's garment relief against the CPU's, summed
# The bent pose wrinkles: garment pixels the CPU evaluation draws off Flat by over
# WRINKLE_CONTRAST grey levels. Measured: 10.5 % of the garments; standing (walk mode at speed 0, as this test
# once froze it), 1.9 % (bands in the hanging sleeves). The bound lies between, 2x from each.
WRINKLE_CONTRAST = 10
MIN_WRINKLED_FRACTION = 0.05
# Of the CPU's wrinkled pixels, the share the GPU draws wrinkled too: measured 1.000 (bent and
# standing); 0.38 with the shader's wrinkle strength halved.
MIN_SHARED_WRINKLES = 0.95
GARMENT_GREEN_MARGIN = 30       # grey levels green stands above red and blue on a green garment
MISSING_DESCRIPTION = "no_such_robot_description"


class DisplayScreenshotTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("test_display_screenshot")
        # Kept under ctest's screenshot folder (build/test_screenshots/display_screenshot) to be looked at.
        cls.directory = os.path.join(os.environ.get("DRESSED_HUMAN_SCREENSHOTS", tempfile.mkdtemp()),
                                     "display_screenshot")
        os.makedirs(cls.directory, exist_ok=True)
        cls.images, cls.outputs = {}, {}
        runs = {mode: {"RELIEF_MODE": mode} for mode in ("Bump mapping", "Flat", "Displaced geometry")}
        # The skeleton drawn through the clothes, on a body with legs twice as thick (Eq. 5 a, b).
        runs["Skeleton and thick legs"] = {"RELIEF_MODE": "Flat", "SHOW_SKELETON": "true", "LEGS_THICKNESS": "2.0"}
        # The other runs let the vertex shader evaluate the patches (the default); this one has
        # the CPU evaluate every vertex, the reference the GPU path must reproduce, wrinkle
        # strength included.
        runs["CPU vertices"] = {"RELIEF_MODE": "Bump mapping", "VERTEX_EVALUATION": "CPU"}
        # GPU vertices asked for, on a GL that offers too few vertex uniforms for the control
        # points (as NVIDIA's usual 1024): the display must fall back to the CPU and say so.
        runs["Small GPU"] = {"RELIEF_MODE": "Bump mapping"}
        # Where the garments are: both in pure green, no relief. Green is far from the skin's hue
        # (red over green over blue) and the grey background in any light, and the pose and view
        # are those of every other run (frozen human, camera on its body frame), so the mask fits
        # them pixel for pixel. Telling the outfit's own colours from the skin instead would tie
        # the mask to this outfit and to hue thresholds in the dark folds and shadows.
        runs["Green garments"] = {"RELIEF_MODE": "Flat", "GARMENT_COLOURS_FROM_FILES": "false",
                                  "UPPER_GARMENT_COLOUR": "0; 255; 0", "LOWER_GARMENT_COLOUR": "0; 255; 0"}
        # From 2.2 m the skin's cells at their true size (a millimetre, issue 40) are under a pixel
        # and rightly not drawn: every run here asks for 2 cm cells, larger than a tile fits on a
        # patch, so each patch holds one tile of 12 cells as before issue 40, and the relief's
        # pipeline (bump mapping, displaced geometry, GPU against CPU) has a skin relief to show.
        for replacements in runs.values():
            replacements["SKIN_CELL_SIZE"] = "0.02"
        environments = {"Small GPU": {"DRESSED_HUMAN_MAX_VERTEX_UNIFORM_VECTORS": "1024"}}
        for name, replacements in runs.items():
            path = os.path.join(cls.directory, name.replace(" ", "_") + ".png")
            with Rviz("display_test.rviz", replacements, environments.get(name)) as rviz:
                cls.images[name] = wait_for_figure(rviz, path)
                cls.outputs[name] = rviz.output()
            rospy.loginfo("screenshot %s: %s", name, path)
        # The log check must see an error the display really prints (issue 37 item 1: it once kept
        # only lines naming the package, which the display's do not): a parameter that is not set.
        with Rviz("display_test.rviz", {"RELIEF_MODE": "Flat", "ROBOT_DESCRIPTION": MISSING_DESCRIPTION}) as rviz:
            time.sleep(10)
            cls.failing_output = rviz.output()

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

    def band(self, image, top, bottom):
        """Figure pixels between two fractions of the figure's height (0 = head top)."""
        mask = figure_mask(image)
        rows = numpy.nonzero(mask.any(axis=1))[0]
        first, height = rows.min(), rows.max() - rows.min()
        band = numpy.zeros_like(mask)
        band[int(first + top * height):int(first + bottom * height)] = True
        return image[mask & band]

    def test_outfit_colours_cover_their_regions(self):
        # Default outfit, jacket + skirt (config/garments): a blue jacket on the chest, a red
        # skirt over the hips, skin on the head.
        image = self.images["Flat"]
        chest, hips, head = self.band(image, 0.2, 0.4), self.band(image, 0.5, 0.6), self.band(image, 0.0, 0.08)
        blue = (chest[:, 2] > chest[:, 0] * 1.2).mean()
        red = ((hips[:, 0] > hips[:, 1] * 1.5) & (hips[:, 0] > hips[:, 2] * 1.2)).mean()
        skin = ((head[:, 0] > head[:, 1]) & (head[:, 1] > head[:, 2])).mean()
        rospy.loginfo("jacket blue %.2f of the chest band, skirt red %.2f of the hip band, skin %.2f of the head",
                      blue, red, skin)
        self.assertGreater(blue, 0.6)
        self.assertGreater(red, 0.6)
        self.assertGreater(skin, 0.6)

    def test_relief_is_visible(self):
        bump, bump_pixels = high_pass_energy(self.images["Bump mapping"], figure_mask(self.images["Bump mapping"]))
        flat, flat_pixels = high_pass_energy(self.images["Flat"], figure_mask(self.images["Flat"]))
        rospy.loginfo("high-pass luminance energy: bump %.3f over %d px, flat %.3f over %d px",
                      bump, bump_pixels, flat, flat_pixels)
        self.assertGreater(bump, 1.5 * flat)

    def test_displaced_geometry_shows_relief(self):
        # The relief moved into the mesh (and its normals) shows like bump mapping does.
        displaced, pixels = high_pass_energy(self.images["Displaced geometry"],
                                             figure_mask(self.images["Displaced geometry"]))
        flat, _ = high_pass_energy(self.images["Flat"], figure_mask(self.images["Flat"]))
        rospy.loginfo("high-pass luminance energy: displaced %.3f over %d px, flat %.3f", displaced, pixels, flat)
        self.assertGreater(displaced, 1.5 * flat)

    def test_skeleton_shows_through_and_legs_grow(self):
        image, flat = self.images["Skeleton and thick legs"], self.images["Flat"]
        # Bright yellow bone lines (1.0, 0.85, 0.1): none in the plain flat image, many here.
        yellow = lambda im: ((im[:, :, 0] > 200) & (im[:, :, 1] > 160) & (im[:, :, 2] < 90)).sum()
        rospy.loginfo("yellow skeleton pixels: %d (flat run: %d)", yellow(image), yellow(flat))
        self.assertGreater(yellow(image), 300)
        self.assertLess(yellow(flat), 30)

        def lower_width(im):
            """Median figure width over the lowest fifth of the figure: the shanks and feet."""
            mask = figure_mask(im)
            rows = numpy.nonzero(mask.any(axis=1))[0]
            first, height = rows.min(), rows.max() - rows.min()
            band = mask[int(first + 0.8 * height):int(first + 0.95 * height)]
            return float(numpy.median(band.sum(axis=1)))
        rospy.loginfo("shank band width: thick legs %.0f px, default %.0f px", lower_width(image), lower_width(flat))
        self.assertGreater(lower_width(image), 1.4 * lower_width(flat))

    def garments(self):
        """The garments' pixels, 2 pixels in from their edges: there a sub-pixel shift of an edge
        between two runs swaps garment for skin or background, which is geometry, not relief."""
        image = self.images["Green garments"]
        green = image[:, :, 1] - numpy.maximum(image[:, :, 0], image[:, :, 2]) > GARMENT_GREEN_MARGIN
        inner = green.copy()
        for dy in range(-2, 3):
            for dx in range(-2, 3):
                inner &= numpy.roll(green, (dy, dx), axis=(0, 1))
        return inner

    def test_gpu_vertices_draw_what_the_cpu_evaluates(self):
        gpu, cpu = self.images["Bump mapping"].astype(float), self.images["CPU vertices"].astype(float)
        flat = self.images["Flat"].astype(float)
        garments = self.garments()
        # The garments' relief shows only where the posed cloth is compressed against its rest
        # shape (wrinkle_placement.h); elsewhere bump mapping draws what Flat draws. The wrinkles
        # each evaluation draws: garment pixels it lights differently from Flat.
        cpu_relief = numpy.abs(cpu - flat).max(axis=2)[garments]
        gpu_relief = numpy.abs(gpu - flat).max(axis=2)[garments]
        cpu_wrinkled = cpu_relief > WRINKLE_CONTRAST
        both_wrinkled = cpu_wrinkled & (gpu_relief > WRINKLE_CONTRAST)
        shared = both_wrinkled.sum() / max(cpu_wrinkled.sum(), 1)
        difference = numpy.abs(gpu - cpu).max(axis=2)[garments]
        relief_ratio = gpu_relief.sum() / max(cpu_relief.sum(), 1.0)
        rospy.loginfo("garments: %d pixels, wrinkled (off Flat by > %d) by the CPU %d = %.1f %%, by both %.3f of "
                      "those; relief GPU/CPU %.3f; GPU against CPU vertices: mean |difference| %.3f, %d pixels = "
                      "%.3f %% above 40, max %.0f", garments.sum(), WRINKLE_CONTRAST, cpu_wrinkled.sum(),
                      100.0 * cpu_wrinkled.mean(), shared, relief_ratio, difference.mean(), (difference > 40).sum(),
                      100.0 * (difference > 40).mean(), difference.max())
        either = figure_mask(self.images["Bump mapping"]) | figure_mask(self.images["CPU vertices"])
        figure_difference = numpy.abs(gpu - cpu).max(axis=2)[either]
        rospy.loginfo("whole figure: mean |difference| %.3f over %d pixels, %d = %.3f %% above 40, max %.0f",
                      figure_difference.mean(), either.sum(), (figure_difference > 40).sum(),
                      100.0 * (figure_difference > 40).mean(), figure_difference.max())
        self.assertGreater(garments.sum(), 20000, "the garments hardly show")
        # The pose bends: compressed cloth, wrinkles where the CPU (the reference) draws them; a
        # standing human has few, and there the shader's wrinkle strength would be compared with
        # the CPU's on next to nothing.
        self.assertGreater(cpu_wrinkled.mean(), MIN_WRINKLED_FRACTION, "too few wrinkles: is the human bent?")
        # The GPU draws the same wrinkles, as strong: the shader's copy of the wrinkle strength is
        # the CPU's.
        self.assertGreater(shared, MIN_SHARED_WRINKLES, "share of the CPU's wrinkled pixels the GPU draws wrinkled")
        self.assertLess(abs(relief_ratio - 1.0), MAX_RELIEF_RATIO_OFF, "GPU relief / CPU relief on the garments")
        self.assertLess(difference.mean(), MAX_MEAN_DIFFERENCE, "garments: mean difference")
        self.assertLessEqual(difference.max(), MAX_PIXEL_DIFFERENCE, "garments: largest difference")
        self.assertLess(figure_difference.mean(), MAX_MEAN_DIFFERENCE, "whole figure: mean difference")
        self.assertLessEqual(figure_difference.max(), MAX_PIXEL_DIFFERENCE, "whole figure: largest difference")
        for name, output in self.outputs.items():
            if name != "Small GPU":
                self.assertNotIn("the CPU evaluates the vertices", output, name)

    def test_small_gpu_falls_back_to_cpu_vertices(self):
        output = self.outputs["Small GPU"]
        self.assertIn("the GPU offers 1024 vertex shader uniform vectors", output)
        self.assertIn("the CPU evaluates the vertices", output)
        fallback, cpu = self.images["Small GPU"].astype(float), self.images["CPU vertices"].astype(float)
        either = figure_mask(self.images["Small GPU"]) | figure_mask(self.images["CPU vertices"])
        difference = numpy.abs(fallback - cpu).max(axis=2)[either]
        rospy.loginfo("small GPU (CPU fallback) against CPU vertices: mean |difference| %.3f over %d figure pixels",
                      difference.mean(), either.sum())
        self.assertGreater(either.sum(), 4000)
        self.assertLess(difference.mean(), 1.0)

    def test_the_log_check_sees_the_display_s_errors(self):
        errors = package_errors(self.failing_output)
        rospy.loginfo("errors logged with Robot Description '%s': %s", MISSING_DESCRIPTION, errors)
        self.assertTrue(any(MISSING_DESCRIPTION in line for line in errors),
                        "no error naming '%s' found by package_errors in:\n%s" % (
                            MISSING_DESCRIPTION, self.failing_output[-3000:]))

    def test_no_error_reported(self):
        for mode, output in self.outputs.items():
            errors = package_errors(output)
            self.assertEqual(errors, [], "%s: %s" % (mode, errors))


if __name__ == "__main__":
    rostest.rosrun("dressed_human", "display_screenshot", DisplayScreenshotTest)
