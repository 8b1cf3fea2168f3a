"""Shared by the display rostests: start rviz on a config, wait for the human, grab the screen."""
import os
import subprocess
import tempfile
import time

import numpy
from PIL import Image

BACKGROUND = numpy.array([48, 48, 48])
HERE = os.path.dirname(os.path.abspath(__file__))


# Placeholders of test/ros/data/display_test.rviz a test need not set.
# SKIN_CELL_SIZE: the display's default, the skin's cells at their true size (issue 40).
DEFAULT_REPLACEMENTS = {"ROBOT_DESCRIPTION": "robot_description", "SHOW_SKELETON": "false", "LEGS_THICKNESS": "1.0", "VERTEX_EVALUATION": "GPU",
                        "SKIN_CELL_SIZE": "0.00107457",
                        "GARMENT_COLOURS_FROM_FILES": "true", "UPPER_GARMENT_COLOUR": "56; 82; 148",
                        "LOWER_GARMENT_COLOUR": "184; 56; 77"}


class Rviz:
    """rviz on a copy of test/ros/data/<template> with text replacements; stopped on exit."""

    def __init__(self, template, replacements, environment=None):
        with open(os.path.join(HERE, "data", template)) as f:
            text = f.read()
        for key, value in {**DEFAULT_REPLACEMENTS, **replacements}.items():
            text = text.replace(key, value)
        self.directory = tempfile.mkdtemp()
        self.config = os.path.join(self.directory, "test.rviz")
        with open(self.config, "w") as f:
            f.write(text)
        self.log_path = os.path.join(self.directory, "rviz.log")
        self.process = None
        self.environment = dict(os.environ, **(environment or {}))

    def __enter__(self):
        self.log = open(self.log_path, "w")
        self.process = subprocess.Popen(["rviz", "-d", self.config, "--disable-anti-aliasing"],
                                        stdout=self.log, stderr=subprocess.STDOUT, env=self.environment)
        return self

    def __exit__(self, *error):
        self.process.terminate()
        try:
            self.process.wait(timeout=20)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()
        self.log.close()

    def output(self):
        with open(self.log_path) as f:
            return f.read()

    def alive(self):
        return self.process.poll() is None


# What this package's programs print in their log lines: the display names itself (rosconsole's
# default format does not print the logger's name, "dressed_human"), the nodes their node type.
PACKAGE_LOG_MARKERS = ("DressedHuman display", "skeleton_publisher", "crowd_publisher", "dressed_human")


def package_errors(output):
    """The ERROR and FATAL lines of `output` that this package's display or nodes printed."""
    return [line for line in output.splitlines()
            if ("[ERROR]" in line or "[FATAL]" in line) and any(marker in line for marker in PACKAGE_LOG_MARKERS)]


def grab(path):
    """The screen, cropped to rviz's 3D view: the bounding box of the background colour."""
    subprocess.run(["import", "-window", "root", path], check=True)
    image = numpy.asarray(Image.open(path).convert("RGB")).astype(numpy.float64)
    background = (image == BACKGROUND).all(axis=2)
    # Rows and columns with many background pixels: stray ones elsewhere (icons) do not count.
    rows = numpy.nonzero(background.sum(axis=1) > 100)[0]
    columns = numpy.nonzero(background.sum(axis=0) > 100)[0]
    if len(rows) < 100 or len(columns) < 100:
        return image[:0, :0]
    return image[rows[0] + 2:rows[-1] - 1, columns[0] + 2:columns[-1] - 1]


def figure_mask(image):
    """Pixels of the 3D view that are not the background: the human."""
    return numpy.abs(image - BACKGROUND).sum(axis=2) > 40


def wait_for_figure(rviz, path, minimum_pixels=4000, timeout=150.0, settle=4.0, still=True):
    """Screenshots until the figure shows (and, if `still`, stops changing); returns the image."""
    deadline = time.time() + timeout
    previous = None
    while time.time() < deadline:
        if not rviz.alive():
            raise RuntimeError("rviz exited:\n" + rviz.output()[-3000:])
        time.sleep(settle)
        image = grab(path)
        mask = figure_mask(image)
        settled = previous is not None and image.shape == previous.shape and numpy.abs(image - previous).mean() < 0.5
        if mask.sum() >= minimum_pixels and (settled or not still):
            return image
        previous = image
    raise RuntimeError("no stable figure on screen within %.0f s (last figure pixels: %d)\n%s"
                       % (timeout, figure_mask(previous).sum() if previous is not None else -1, rviz.output()[-3000:]))


def high_pass_energy(image, mask):
    """Mean squared difference between luminance and its 5x5 box blur, inside the mask: the fine
    relief, not the large-scale shading of the limbs."""
    luminance = image @ numpy.array([0.299, 0.587, 0.114])
    padded = numpy.pad(luminance, 2, mode="edge")
    blurred = sum(padded[dy:dy + luminance.shape[0], dx:dx + luminance.shape[1]]
                  for dy in range(5) for dx in range(5)) / 25.0
    # Stay away from the silhouette, where the background leaks into the blur.
    inner = mask.copy()
    for shift in ((0, 3), (0, -3), (3, 0), (-3, 0)):
        inner &= numpy.roll(mask, shift, axis=(0, 1))
    return float(((luminance - blurred) ** 2)[inner].mean()), int(inner.sum())
