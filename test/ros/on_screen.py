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
from collections import namedtuple

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


# rviz's grid in the shipped configs (colour 160; 160; 164, alpha 0.5) over their background
# (48; 48; 48): one line, and two crossing.
BACKGROUND_COLOUR = (48, 48, 48)
GRID_COLOURS = ((104, 104, 106), (132, 132, 135))


def drawn_mask(image, background=BACKGROUND_COLOUR, grid=GRID_COLOURS):
    """Pixels that are neither background nor grid: every pixel of the figures, dark and grey
    garments too (figure_mask misses those). Exact only with rviz's anti-aliasing disabled, which
    keeps the background and the grid lines those pure colours."""
    image = numpy.asarray(image, dtype=float)
    mask = numpy.ones(image.shape[:2], dtype=bool)
    for colour in (background,) + tuple(grid):
        mask &= numpy.abs(image - numpy.array(colour, dtype=float)).max(axis=2) > 1.0
    return mask


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
    """Where TF says the human is at one instant (`at`; the newest by default): bone frame origins
    and the view's target."""

    def __init__(self, buffer, view, frames, root=ROOT_FRAME, at=None):
        wait = rospy.Duration(0.5) if at is None else rospy.Duration(0)  # the past is there or not
        at = rospy.Time(0) if at is None else at

        def position(frame):
            t = buffer.lookup_transform(view.fixed_frame, frame, at, wait).transform
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
    jump in them is the loop itself.

    It also keeps, per root frame (ROOT_FRAME or ROOT_FRAME_<id>), the first and newest stamp of its
    current stay on TF (HumansOnTf reads which humans are there now), and hands each /tf message
    to `on_message` once it is in the buffer."""

    JUMP_SECONDS = 1.0
    # A root frame silent this long and back again is a new stay (a track id that came back).
    STAY_GAP_SECONDS = 1.0

    def __init__(self, buffer, on_message=None):
        self.buffer = buffer
        self.static = {}
        self.newest = None
        self.root_stays = {}  # root frame: [first stamp, newest stamp] of its current stay
        self.on_message = on_message
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
                    self.root_stays.clear()
                self.buffer.set_transform(transform, "looping_tf_listener")
                self.newest = stamp if self.newest is None else max(self.newest, stamp)
                child = transform.child_frame_id
                if child == ROOT_FRAME or child.startswith(ROOT_FRAME + "_"):
                    stay = self.root_stays.get(child)
                    if stay is None or (stamp - stay[1]).to_sec() > self.STAY_GAP_SECONDS:
                        self.root_stays[child] = [stamp, stamp]
                    else:
                        stay[1] = stamp
            if self.on_message is not None:
                self.on_message(message)

    def on_static(self, message):
        with self.lock:
            for transform in message.transforms:
                self.static[transform.child_frame_id] = transform
                self.buffer.set_transform_static(transform, "looping_tf_listener")


# The humans to look up at one instant: `humans` {root frame: bone frames}; `unjudged`, those of
# them to box but not to judge; `stamp`, the TF tick they were found in (None for a fixed set of
# humans); `seconds_on_tf` {root frame: how long it has been on TF} (HumansOnTf only).
HumansNow = namedtuple("HumansNow", "humans unjudged stamp seconds_on_tf")


class HumansOnTf:
    """The humans a crowd publisher has on TF now, found by their root frames ROOT_FRAME_<id>
    (skeleton_tf: each with its bone frames `<bone>_<id>`), for a crowd whose people come and go.

    The publisher sends every human of one tick in one /tf message, all with the tick's stamp: the
    humans now are the roots whose newest stamp is the newest of all roots; an older one has left.
    Boxed but not judged: one first seen on TF less than `settle_seconds` before (the display may
    not have built its figure yet), and one gone from TF less than `linger_seconds` before (the
    display keeps a human missing from the crowd messages for a second, CrowdTopic::kTimeoutSeconds,
    at its last pose, which TF still holds)."""

    def __init__(self, listener, frames, settle_seconds=1.0, linger_seconds=1.5):
        self.listener = listener
        self.bones = [frame for frame in frames if frame != ROOT_FRAME]
        self.settle = rospy.Duration(settle_seconds)
        self.linger = rospy.Duration(linger_seconds)

    def now(self):
        with self.listener.lock:
            stays = {root: list(stay) for root, stay in self.listener.root_stays.items()}
        if not stays:
            return HumansNow({}, set(), None, {})
        newest = max(stay[1] for stay in stays.values())
        shown = {root: stay for root, stay in stays.items() if newest - stay[1] <= self.linger}
        humans = {root: [root] + [bone + root[len(ROOT_FRAME):] for bone in self.bones] for root in shown}
        unjudged = {root for root, (first, last) in shown.items() if last != newest or newest - first < self.settle}
        seconds_on_tf = {root: round((last - first).to_sec(), 2) for root, (first, last) in shown.items()}
        return HumansNow(humans, unjudged, newest, seconds_on_tf)


def clip(box, width, height):
    left, top, right, bottom = box
    return max(left, 0.0), max(top, 0.0), min(right, float(width)), min(bottom, float(height))


def area(box):
    left, top, right, bottom = box
    return max(0.0, right - left) * max(0.0, bottom - top)


def union(a, b):
    return b if a is None else (min(a[0], b[0]), min(a[1], b[1]), max(a[2], b[2]), max(a[3], b[3]))


def human_box(view, poses, width, height, margin_metres=BODY_MARGIN_METRES, earlier_poses=()):
    """Where one human's frames project at the instants of `poses`: the tight box of its frames,
    that box grown by the body's reach (and by the grown boxes of `earlier_poses`, where the view
    may still show it), whether its root is well inside the view at every instant of `poses`,
    whether the grown box touches the view (or part of it is behind the camera), and the pixels
    (column, row) its frames project to at every instant."""
    tight, grown, root_inside, touches, points = None, None, True, False, []
    for earlier, pose in [(False, pose) for pose in poses] + [(True, pose) for pose in earlier_poses]:
        columns, rows, depth, scale = view.project(pose.bones, pose.target, width, height)
        root_column, root_row, root_depth, _ = view.project(pose.root[None, :], pose.target, width, height)
        if (depth <= view.near).any():
            root_inside &= earlier
            touches = True  # part of it behind the camera: not judged
            continue
        points.append(numpy.stack([columns, rows], axis=1))
        margin = scale * margin_metres / depth.min() + 6.0
        box = (columns.min(), rows.min(), columns.max(), rows.max())
        big = (box[0] - margin, box[1] - margin, box[2] + margin, box[3] + margin)
        grown = union(grown, big)
        touches |= area(clip(big, width, height)) > 0
        if earlier:
            continue
        tight = union(tight, box)
        inset_w, inset_h = 0.03 * width, 0.03 * height
        root_inside &= bool(root_depth[0] > view.near and inset_w < root_column[0] < width - inset_w and
                            inset_h < root_row[0] < height - inset_h)
    points = numpy.concatenate(points) if points else numpy.zeros((0, 2))
    return tight, grown, root_inside and tight is not None, touches, points


def pixel_owners(mask, regions, points):
    """For each figure pixel of `mask` (in numpy.nonzero order), the index of the human it is
    nearest to, among those whose region (rows, columns slices) holds it: nearest by the pixels
    its frames project to (`points`, one array per human); -1 where no region holds it."""
    rows, columns = numpy.nonzero(mask)
    best = numpy.full(rows.shape, numpy.inf)
    owners = numpy.full(rows.shape, -1)
    for index, (region, human_points) in enumerate(zip(regions, points)):
        inside = ((rows >= region[0].start) & (rows < region[0].stop) &
                  (columns >= region[1].start) & (columns < region[1].stop))
        if not inside.any() or len(human_points) == 0:
            continue
        pixels = numpy.stack([columns[inside], rows[inside]], axis=1).astype(float)
        distance = ((pixels[:, None, :] - human_points[None, :, :]) ** 2).sum(axis=2).min(axis=1)
        nearer = numpy.nonzero(inside)[0][distance < best[inside]]
        best[nearer] = distance[distance < best[inside]]
        owners[nearer] = index
    return owners


def judge_humans(image, view, poses_by_human, margin_metres=BODY_MARGIN_METRES, unjudged=(), nearest_pixels=False,
                 earlier_poses_by_human=None, mask_of=figure_mask):
    """One screenshot against the poses TF gave each human just before and just after it was taken
    (and `earlier_poses_by_human`: poses before those, where rviz may still draw it: they only grow
    its box).

    Per human, in:  its root frame projects well inside the view at both instants: the figure must
                    cover enough of the box its frames project to (grown by the body's reach);
              out:  its grown box misses the view at both instants;
              edge: partly in view (or behind the camera): recorded, not judged;
              no TF: TF had none of its poses;
              unjudged: named in `unjudged` (coming or going during the shot): boxed, not judged.
    And for the whole view: with a human in, the figure is drawn nowhere outside the humans'
    grown boxes; with every human out, nothing is drawn at all.

    nearest_pixels (a dense crowd, whose boxes overlap): a figure pixel counts for one human only,
    the one whose frames project nearest to it among those whose grown box holds it (otherwise a
    neighbour's figure in the overlap would stand in for a human not drawn), and the figure may
    show outside the boxes by a tenth of one human's, not of all. mask_of: which pixels are figure
    (figure_mask, or drawn_mask).
    """
    height, width = image.shape[:2]
    mask = mask_of(image)
    covered = numpy.zeros(mask.shape, dtype=bool)
    humans, regions, points = {}, {}, {}
    for name, poses in poses_by_human.items():
        if not poses:
            humans[name] = {"state": "no TF", "ok": True}
            continue
        earlier = (earlier_poses_by_human or {}).get(name, ())
        tight, grown, root_inside, touches, points[name] = human_box(view, poses, width, height, margin_metres, earlier)
        human = {}
        if grown is not None:
            left, top, right, bottom = (int(round(v)) for v in clip(grown, width, height))
            regions[name] = (slice(max(top, 0), max(bottom, 0)), slice(max(left, 0), max(right, 0)))
            covered[regions[name]] = True
            human.update(inside=int(mask[regions[name]].sum()), grown_box=[round(v, 1) for v in grown])
        if tight is not None:
            human["tight_box"] = [round(v, 1) for v in tight]
        if name in unjudged:
            human.update(state="unjudged", ok=True)
        elif root_inside:
            human.update(state="in", needed=max(40, int(0.12 * area(clip(tight, width, height)))))
        else:
            human.update(state="out" if not touches else "edge", ok=True)
        humans[name] = human
    if nearest_pixels:
        names = list(regions)
        owners = pixel_owners(mask, [regions[name] for name in names], [points[name] for name in names])
        counts = numpy.bincount(owners[owners >= 0], minlength=len(names))
        for name, count in zip(names, counts):
            humans[name]["inside"] = int(count)
    for human in humans.values():
        if human["state"] == "in":
            human["ok"] = human["inside"] >= human["needed"]
    total = int(mask.sum())
    outside = total - int((mask & covered).sum())
    states = [human["state"] for human in humans.values()]
    # What may show outside the boxes (stray edge pixels): a tenth of the figures, and of a crowd a
    # tenth of one figure, since a tenth of all of them would let a whole human be drawn astray.
    drawn = (total - outside) / (max(1, len(regions)) if nearest_pixels else 1)
    if any(state in ("in", "unjudged") for state in states):
        view_ok = outside <= max(150, 0.1 * drawn)
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


def humans_now(frames):
    """HumansNow of `frames`: a HumansOnTf, a list of one human's frames or {root frame: bone frames}."""
    if isinstance(frames, HumansOnTf):
        return frames.now()
    return HumansNow(as_humans(frames), set(), None, {})


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


def poses_before(buffer, view, humans, stamp, seconds, step=0.1):
    """Each human's poses TF had over the `seconds` before `stamp`, every `step` s (those TF has)."""
    poses = {root: [] for root in humans}
    for k in range(1, int(round(seconds / step)) + 1):
        at = stamp - rospy.Duration(k * step)
        for root, frames in humans.items():
            try:
                poses[root].append(Pose(buffer, view, frames, root, at))
            except tf2_ros.TransformException:
                pass  # not on TF yet then
    return poses


def wait_for_view(launch, buffer, view, frames, path, timeout=120.0):
    """Until rviz shows its 3D view and TF has every bone frame of every human (`frames`: a list,
    {root frame: frames} for several humans, or a HumansOnTf: at least one human on TF)."""
    deadline = time.time() + timeout
    while time.time() < deadline:
        if not launch.alive():
            raise RuntimeError("roslaunch exited:\n" + launch.output()[-3000:])
        time.sleep(1.0)
        humans = humans_now(frames).humans
        if not humans or None in poses_now(buffer, view, humans, -1, "yet").values():
            continue
        if grab(path).size > 0:
            return
    raise RuntimeError("no rviz view with the humans' TF within %.0f s:\n%s" % (timeout, launch.output()[-3000:]))


def observe(launch, buffer, view, frames, directory, seconds=42.0, interval=2.5, margin_metres=BODY_MARGIN_METRES,
            nearest_pixels=False, lag_seconds=0.0, mask_of=figure_mask):
    """A screenshot every `interval` s for `seconds`, each judged; saved with a summary.json.
    `frames`: one human's bone frames (its verdict at the top level of each result),
    {root frame: bone frames} for several (verdicts under "humans"), or a HumansOnTf for a crowd
    that comes and goes (the humans on TF at each shot; one there only before or only after the
    screenshot is boxed but not judged, as HumansOnTf's unjudged; each human's "seconds_on_tf" and
    the result's "tf_stamp", the TF tick before the screenshot, are recorded), each box grown by
    `margin_metres`; nearest_pixels, mask_of: see judge_humans. lag_seconds (HumansOnTf only): rviz may
    draw a human up to this long behind the TF read before the screenshot: its box covers its
    poses over that time too (stretched behind a walker, not grown all round)."""
    os.makedirs(directory, exist_ok=True)
    results = []
    start = time.time()
    shot = 0
    while shot * interval <= seconds:
        time.sleep(max(0.0, start + shot * interval - time.time()))
        if not launch.alive():
            raise RuntimeError("roslaunch exited during the observation:\n" + launch.output()[-3000:])
        path = os.path.join(directory, "shot_%02d.png" % shot)
        now_before = humans_now(frames)
        before = poses_now(buffer, view, now_before.humans, shot, "before")
        image = grab(path)
        now_after = humans_now(frames)
        after = poses_now(buffer, view, now_after.humans, shot, "after")
        roots = sorted(set(now_before.humans) | set(now_after.humans))
        poses = {root: [p for p in (before.get(root), after.get(root)) if p is not None] for root in roots}
        earlier = {}
        if lag_seconds > 0 and now_before.stamp is not None:
            earlier = poses_before(buffer, view, now_before.humans, now_before.stamp, lag_seconds)
        # Coming or going while the screen was read: it may or may not be in the picture.
        unjudged = (set(now_before.humans) ^ set(now_after.humans)) | now_before.unjudged | now_after.unjudged
        if image.size == 0:
            result = {"state": "no view", "ok": False}
        elif not isinstance(frames, list):
            result = judge_humans(image, view, poses, margin_metres, unjudged, nearest_pixels, earlier, mask_of)
            for root, seconds_on_tf in now_before.seconds_on_tf.items():
                result["humans"][root]["seconds_on_tf"] = seconds_on_tf
        elif not poses[ROOT_FRAME]:
            result = {"state": "no TF", "ok": True}
        else:
            result = judge(image, view, poses[ROOT_FRAME])
        result.update(shot=shot, seconds=round(time.time() - start, 1), path=path)
        if now_before.stamp is not None:
            result["tf_stamp"] = now_before.stamp.to_sec()
            result["tf_stamp_after"] = now_after.stamp.to_sec()
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
