"""What a user sees over time: a shipped launch file runs with the human moving, a screenshot is
taken every few seconds, and each one is judged against where TF says the human is.

The camera is rviz's Orbit view, computed from the rviz config the way OrbitViewController does
(eye at focal point + distance (cos yaw cos pitch, sin yaw cos pitch, sin pitch), in the target
frame's position, z up), so a bone frame's pixel follows from its TF pose alone.
"""
import json
import math
import os
import signal
import subprocess
import threading
import time
import xml.etree.ElementTree as ElementTree

import numpy
import rospy
import tf2_ros
import yaml
from PIL import Image
from tf2_msgs.msg import TFMessage

from screenshots import grab

ROOT_FRAME = "body"
# A bone frame sits on the bone's axis at its proximal joint; the skin and clothes reach this far
# beyond the frames (head top above the head frame, hands, skirt hem).
BODY_MARGIN_METRES = 0.35


def figure_mask(image):
    """Pixels of the human in a view with rviz's grey grid: the skin and garments are coloured
    (the grid and background are grey and at most ~135 bright), highlights are bright."""
    highest, lowest = image.max(axis=2), image.min(axis=2)
    return ((highest - lowest) > 20) | (highest > 175)


def bone_frames(urdf_text):
    """The bone frames of the URDF (links that are not the intermediate joint links)."""
    links = [link.get("name") for link in ElementTree.fromstring(urdf_text).iter("link")]
    return [name for name in links if not name.endswith("_ry_link") and not name.endswith("_rx_link")]


class OrbitView:
    """rviz's Orbit view controller: the eye orbits the focal point (relative to the target
    frame's position) at `distance`, `yaw` and `pitch`, z up, vertical field of view `fov`."""

    def __init__(self, distance, yaw, pitch, focal=(0.0, 0.0, 0.0), fixed_frame="world", target_frame=None,
                 fov=math.pi / 4, near=0.01):
        self.fixed_frame = fixed_frame
        self.target_frame = target_frame or fixed_frame
        self.distance, self.yaw, self.pitch = float(distance), float(yaw), float(pitch)
        self.focal = numpy.array(focal, dtype=float)
        self.fov, self.near = float(fov), float(near)

    @classmethod
    def from_config(cls, config_path):
        """The current view of an rviz config file."""
        with open(config_path) as f:
            config = yaml.safe_load(f)
        manager = config["Visualization Manager"]
        view = manager["Views"]["Current"]
        if view["Class"] != "rviz/Orbit":
            raise ValueError("%s: the view is %s, only rviz/Orbit is modelled" % (config_path, view["Class"]))
        fixed = manager["Global Options"]["Fixed Frame"]
        target = view.get("Target Frame", "<Fixed Frame>")
        focal = view.get("Focal Point", {"X": 0, "Y": 0, "Z": 0})
        return cls(view["Distance"], view["Yaw"], view["Pitch"], (focal["X"], focal["Y"], focal["Z"]), fixed,
                   fixed if target == "<Fixed Frame>" else target, view.get("Field of View", math.pi / 4),
                   view.get("Near Clip Distance", 0.01))

    def project(self, points, target_position, width, height):
        """Pixel columns, rows and depths of fixed-frame points in a width x height view."""
        focal_point = target_position + self.focal
        offset = numpy.array([math.cos(self.yaw) * math.cos(self.pitch), math.sin(self.yaw) * math.cos(self.pitch),
                              math.sin(self.pitch)])
        eye = focal_point + self.distance * offset
        forward = -offset
        right = numpy.cross(forward, [0.0, 0.0, 1.0])
        right /= numpy.linalg.norm(right)
        up = numpy.cross(right, forward)
        relative = numpy.asarray(points) - eye
        depth = relative @ forward
        scale = (height / 2.0) / math.tan(self.fov / 2.0)  # pixels per unit of x/z at the view plane
        safe = numpy.where(depth > 1e-6, depth, 1e-6)
        columns = width / 2.0 + scale * (relative @ right) / safe
        rows = height / 2.0 - scale * (relative @ up) / safe
        return columns, rows, depth, scale


def figure_pixels_in_box(image, view, low, high, target=numpy.zeros(3)):
    """Figure pixels inside the screen rectangle an axis-aligned fixed-frame box projects to."""
    height, width = image.shape[:2]
    corners = numpy.array([[x, y, z] for x in (low[0], high[0]) for y in (low[1], high[1]) for z in (low[2], high[2])])
    columns, rows, depth, _ = view.project(corners, target, width, height)
    if (depth <= view.near).any():
        return 0
    left, top, right, bottom = (int(round(v)) for v in clip((columns.min(), rows.min(), columns.max(), rows.max()),
                                                            width, height))
    return int(figure_mask(image)[max(top, 0):max(bottom, 0), max(left, 0):max(right, 0)].sum())


class Pose:
    """Where TF says the human is at one instant: bone frame origins and the view's target."""

    def __init__(self, buffer, view, frames, root=ROOT_FRAME):
        def position(frame):
            t = buffer.lookup_transform(view.fixed_frame, frame, rospy.Time(0), rospy.Duration(0.5)).transform
            return numpy.array([t.translation.x, t.translation.y, t.translation.z])
        self.bones = numpy.array([position(frame) for frame in frames])
        self.root = position(root)
        self.target = position(view.target_frame) if view.target_frame != view.fixed_frame else numpy.zeros(3)


class LoopingTfListener:
    """Fills a tf2 buffer from /tf and /tf_static, and empties it when the transforms' stamps jump
    back (a bag replayed in a loop).

    tf2_ros's own listener clears its buffer when the clock jumps back, but /clock and /tf arrive
    on different threads: a last transform of the old loop handled after the clear stays the newest
    in the buffer, the new loop's transforms are older than it, and every latest-time lookup
    returns that one stale pose until the next loop. The stamps of one topic arrive in order, so a
    jump in them is the loop itself."""

    JUMP_SECONDS = 1.0

    def __init__(self, buffer):
        self.buffer = buffer
        self.static = {}
        self.newest = None
        self.lock = threading.Lock()
        self.subscribers = [rospy.Subscriber("/tf", TFMessage, self.on_transforms, queue_size=1000),
                            rospy.Subscriber("/tf_static", TFMessage, self.on_static, queue_size=100)]

    def on_transforms(self, message):
        with self.lock:
            for transform in message.transforms:
                stamp = transform.header.stamp
                if self.newest is not None and stamp < self.newest - rospy.Duration(self.JUMP_SECONDS):
                    self.buffer.clear()
                    for static in self.static.values():
                        self.buffer.set_transform_static(static, "looping_tf_listener")
                    self.newest = None
                self.buffer.set_transform(transform, "looping_tf_listener")
                self.newest = stamp if self.newest is None else max(self.newest, stamp)

    def on_static(self, message):
        with self.lock:
            for transform in message.transforms:
                self.static[transform.child_frame_id] = transform
                self.buffer.set_transform_static(transform, "looping_tf_listener")


def clip(box, width, height):
    left, top, right, bottom = box
    return max(left, 0.0), max(top, 0.0), min(right, float(width)), min(bottom, float(height))


def area(box):
    left, top, right, bottom = box
    return max(0.0, right - left) * max(0.0, bottom - top)


def human_box(view, poses, width, height, margin_metres=BODY_MARGIN_METRES):
    """Where one human's frames project at the instants of `poses`: the tight box of its frames,
    that box grown by the body's reach, whether its root is well inside the view at every instant,
    and whether the grown box touches the view (or part of it is behind the camera)."""
    tight, grown, root_inside, touches = None, None, True, False
    for pose in poses:
        columns, rows, depth, scale = view.project(pose.bones, pose.target, width, height)
        root_column, root_row, root_depth, _ = view.project(pose.root[None, :], pose.target, width, height)
        if (depth <= view.near).any():
            root_inside = False
            touches = True  # part of it behind the camera: not judged
            continue
        margin = scale * margin_metres / depth.min() + 6.0
        box = (columns.min(), rows.min(), columns.max(), rows.max())
        big = (box[0] - margin, box[1] - margin, box[2] + margin, box[3] + margin)
        tight = box if tight is None else (min(tight[0], box[0]), min(tight[1], box[1]), max(tight[2], box[2]), max(tight[3], box[3]))
        grown = big if grown is None else (min(grown[0], big[0]), min(grown[1], big[1]), max(grown[2], big[2]), max(grown[3], big[3]))
        inset_w, inset_h = 0.03 * width, 0.03 * height
        root_inside &= bool(root_depth[0] > view.near and inset_w < root_column[0] < width - inset_w and
                            inset_h < root_row[0] < height - inset_h)
        touches |= area(clip(big, width, height)) > 0
    return tight, grown, root_inside and grown is not None, touches


def judge_humans(image, view, poses_by_human, margin_metres=BODY_MARGIN_METRES):
    """One screenshot against the poses TF gave each human just before and just after it was taken.

    Per human, in:  its root frame projects well inside the view at both instants: the figure must
                    cover enough of the box its frames project to (grown by the body's reach);
              out:  its grown box misses the view at both instants;
              edge: partly in view (or behind the camera): recorded, not judged;
              no TF: TF had none of its poses.
    And for the whole view: with a human in, the figure is drawn nowhere outside the humans'
    grown boxes; with every human out, nothing is drawn at all.
    """
    height, width = image.shape[:2]
    mask = figure_mask(image)
    covered = numpy.zeros(mask.shape, dtype=bool)
    humans = {}
    for name, poses in poses_by_human.items():
        if not poses:
            humans[name] = {"state": "no TF", "ok": True}
            continue
        tight, grown, root_inside, touches = human_box(view, poses, width, height, margin_metres)
        human = {}
        if grown is not None:
            left, top, right, bottom = (int(round(v)) for v in clip(grown, width, height))
            region = (slice(max(top, 0), max(bottom, 0)), slice(max(left, 0), max(right, 0)))
            covered[region] = True
            human.update(inside=int(mask[region].sum()), tight_box=[round(v, 1) for v in tight],
                         grown_box=[round(v, 1) for v in grown])
        if root_inside:
            human.update(state="in", needed=max(40, int(0.12 * area(clip(tight, width, height)))))
            human["ok"] = human["inside"] >= human["needed"]
        else:
            human.update(state="out" if not touches else "edge", ok=True)
        humans[name] = human
    total = int(mask.sum())
    outside = total - int((mask & covered).sum())
    states = [human["state"] for human in humans.values()]
    if "in" in states:
        view_ok = outside <= max(150, 0.1 * (total - outside))
    elif all(state == "out" for state in states):
        view_ok = total <= 100
    else:
        view_ok = True
    return {"figure_pixels": total, "view": [width, height], "outside": outside, "humans": humans,
            "ok": view_ok and all(human["ok"] for human in humans.values())}


def judge(image, view, poses):
    """judge_humans for one human, its verdict at the top level."""
    result = judge_humans(image, view, {ROOT_FRAME: poses})
    human = result.pop("humans")[ROOT_FRAME]
    human["ok"] = result["ok"]
    result.update(human)
    return result


def crowd_frames(frames, suffixes):
    """Each human's bone frames by its root frame: `frames` with `_<id>` appended per suffix."""
    return {ROOT_FRAME + suffix: [frame + suffix for frame in frames] for suffix in suffixes}


class Launch:
    """`roslaunch dressed_human <file> <args>` on the test's master; output to a log file."""

    def __init__(self, launch_file, arguments, log_path):
        self.log_path = log_path
        self.log = open(log_path, "w")
        self.process = subprocess.Popen(["roslaunch", "dressed_human", launch_file] + list(arguments),
                                        stdout=self.log, stderr=subprocess.STDOUT, start_new_session=True)

    def alive(self):
        return self.process.poll() is None

    def stop(self):
        if self.alive():
            self.process.send_signal(signal.SIGINT)
            try:
                self.process.wait(timeout=30)
            except subprocess.TimeoutExpired:
                os.killpg(self.process.pid, signal.SIGKILL)
                self.process.wait()
        self.log.close()

    def output(self):
        with open(self.log_path) as f:
            return f.read()


def as_humans(frames):
    """{root frame: bone frames}: a list of frames is the one human rooted at ROOT_FRAME."""
    return frames if isinstance(frames, dict) else {ROOT_FRAME: frames}


def poses_now(buffer, view, humans, shot, when):
    """Each human's pose from TF now, or None where TF lacks it."""
    poses = {}
    for root, frames in humans.items():
        try:
            poses[root] = Pose(buffer, view, frames, root)
        except tf2_ros.TransformException as error:
            rospy.logwarn("shot %d: no TF %s for %s: %s", shot, when, root, error)
            poses[root] = None
    return poses


def wait_for_view(launch, buffer, view, frames, path, timeout=120.0):
    """Until rviz shows its 3D view and TF has every bone frame of every human (`frames`: a list,
    or {root frame: frames} for several humans)."""
    deadline = time.time() + timeout
    while time.time() < deadline:
        if not launch.alive():
            raise RuntimeError("roslaunch exited:\n" + launch.output()[-3000:])
        time.sleep(1.0)
        if None in poses_now(buffer, view, as_humans(frames), -1, "yet").values():
            continue
        if grab(path).size > 0:
            return
    raise RuntimeError("no rviz view with the humans' TF within %.0f s:\n%s" % (timeout, launch.output()[-3000:]))


def observe(launch, buffer, view, frames, directory, seconds=42.0, interval=2.5, margin_metres=BODY_MARGIN_METRES):
    """A screenshot every `interval` s for `seconds`, each judged; saved with a summary.json.
    `frames`: one human's bone frames (its verdict at the top level of each result), or
    {root frame: bone frames} for several (verdicts under "humans"), each box grown by
    `margin_metres`."""
    os.makedirs(directory, exist_ok=True)
    humans = as_humans(frames)
    results = []
    start = time.time()
    shot = 0
    while shot * interval <= seconds:
        time.sleep(max(0.0, start + shot * interval - time.time()))
        if not launch.alive():
            raise RuntimeError("roslaunch exited during the observation:\n" + launch.output()[-3000:])
        path = os.path.join(directory, "shot_%02d.png" % shot)
        before = poses_now(buffer, view, humans, shot, "before")
        image = grab(path)
        after = poses_now(buffer, view, humans, shot, "after")
        poses = {root: [p for p in (before[root], after[root]) if p is not None] for root in humans}
        if image.size == 0:
            result = {"state": "no view", "ok": False}
        elif isinstance(frames, dict):
            result = judge_humans(image, view, poses, margin_metres)
        elif not poses[ROOT_FRAME]:
            result = {"state": "no TF", "ok": True}
        else:
            result = judge(image, view, poses[ROOT_FRAME])
        result.update(shot=shot, seconds=round(time.time() - start, 1), path=path)
        if image.size > 0:
            Image.fromarray(image.astype(numpy.uint8)).save(path)  # the 3D view only
        rospy.loginfo("shot %02d at %5.1f s: %s", shot, result["seconds"],
                      {k: v for k, v in result.items() if k not in ("path", "shot", "seconds")})
        results.append(result)
        shot += 1
    with open(os.path.join(directory, "summary.json"), "w") as f:
        json.dump(results, f, indent=1)
    return results


def edited_config(source, destination, display_changes=None, view_changes=None):
    """A copy of an rviz config with some DressedHuman display properties and view fields set."""
    with open(source) as f:
        config = yaml.safe_load(f)
    manager = config["Visualization Manager"]
    for display in manager["Displays"]:
        if display.get("Class") == "dressed_human/DressedHuman":
            display.update(display_changes or {})
    manager["Views"]["Current"].update(view_changes or {})
    with open(destination, "w") as f:
        yaml.safe_dump(config, f, default_flow_style=False)
    return destination
