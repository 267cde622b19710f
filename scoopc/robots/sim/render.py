"""Pictures of a run (pillow): a PNG of the world and the robots' trajectories, and an animated GIF."""

import math

from PIL import Image, ImageDraw

COLORS = [(31, 119, 180), (255, 127, 14), (44, 160, 44), (148, 103, 189), (140, 86, 75), (23, 190, 207)]
MARGIN = 10
HEADER = 22  # the band above the world: the title (and the GIF's time stamp), clear of the paths
ROW = 16  # one row of the legend below the world
BLACK, GREY, DARK, RED, MAGENTA = (0, 0, 0), (150, 150, 150), (40, 40, 40), (255, 0, 0), (255, 0, 255)
STATION, STATION_FILL, GOAL = (0, 170, 0), (210, 255, 210), (220, 0, 0)


class _Canvas:
    """The world drawn once (floor, holes, boxes, walls, station, goal) with its title band, scale
    bar and legend, and its coordinate transform. `labels` lists what the picture names."""

    def __init__(self, sim, pixels_per_metre=None, max_pixels=1000, title=""):
        w = sim.world
        self.scale = pixels_per_metre or max(20.0, min(200.0, max_pixels / max(w.width, w.height)))
        width = max(int(w.width * self.scale) + 2 * MARGIN, 260)
        self.legend = _legend_entries(sim)
        per_row = max(1, (width - 2 * MARGIN) // 120)
        rows = 1 + (len(self.legend) + per_row - 1) // per_row  # the scale bar's row, then the legend
        self.world_height = int(w.height * self.scale) + 2 * MARGIN
        self.size = (width, HEADER + self.world_height + rows * ROW + MARGIN // 2)
        self.image = Image.new("RGB", self.size, (255, 255, 255))
        self.labels = [f"title: {title}"] if title else []
        d = ImageDraw.Draw(self.image)
        self._world(d, w)
        if title:
            d.text((MARGIN, 5), title, fill=BLACK)
        top = HEADER + self.world_height
        self.labels.append(f"scale: {self._scale_bar(d, top)}")
        self._legend(d, top + ROW, per_row)

    def _world(self, d, w):
        px = self.px
        for poly in w.holes:
            d.polygon([px(x, y) for x, y in poly], fill=DARK)
        for x0, y0, x1, y1 in w.boxes:
            d.rectangle([px(x0, y1), px(x1, y0)], fill=GREY)
        for x0, y0, x1, y1 in w.segments:
            d.line([px(x0, y0), px(x1, y1)], fill=BLACK, width=2)
        if w.station is not None:
            cx, cy = px(*w.station)
            r = w.station_radius * self.scale
            d.ellipse([cx - r, cy - r, cx + r, cy + r], outline=STATION, width=2, fill=STATION_FILL)
        if w.goal is not None:
            _cross(d, *px(*w.goal), GOAL, 6)

    def _scale_bar(self, d, top) -> str:
        """A bar of a round length (at most a third of the picture's width); returns its text."""
        metres = 1.0
        for candidate in (0.1, 0.2, 0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 50.0):
            if candidate * self.scale <= (self.size[0] - 2 * MARGIN) / 3:
                metres = candidate
        text = f"{metres:g} m"
        y = top + ROW // 2
        x1 = MARGIN + metres * self.scale
        d.line([MARGIN, y, x1, y], fill=BLACK, width=2)
        d.line([MARGIN, y - 4, MARGIN, y + 4], fill=BLACK, width=1)
        d.line([x1, y - 4, x1, y + 4], fill=BLACK, width=1)
        d.text((x1 + 6, y - 6), text, fill=BLACK)
        return text

    def _legend(self, d, top, per_row):
        for index, (name, draw) in enumerate(self.legend):
            x = MARGIN + (index % per_row) * 120
            y = top + (index // per_row) * ROW + ROW // 2
            draw(d, x + 6, y)
            d.text((x + 16, y - 6), name, fill=BLACK)
            self.labels.append(name)

    def px(self, x, y):
        return (MARGIN + x * self.scale, HEADER + self.world_height - MARGIN - y * self.scale)

    def marks(self, d, robot, color, until=math.inf):
        """Start square, collisions (red dots) and the fall (magenta cross) up to time `until`."""
        _start(d, *self.px(*robot.spec.start[:2]), color)
        for t, cx, cy in robot.collisions:
            if t <= until:
                _dot(d, *self.px(cx, cy), RED)
        if robot.fell_at is not None and robot.fell_at[0] <= until:
            _cross(d, *self.px(*robot.fell_at[1:]), MAGENTA, 8)

    def body(self, d, robot, x, y, theta, color):
        """The robot's disc and a heading line."""
        ex, ey = self.px(x, y)
        r = robot.spec.radius * self.scale
        d.ellipse([ex - r, ey - r, ex + r, ey + r], outline=color, width=2)
        hx, hy = self.px(x + robot.spec.radius * math.cos(theta), y + robot.spec.radius * math.sin(theta))
        d.line([ex, ey, hx, hy], fill=color, width=2)


def _start(d, x, y, color):
    d.rectangle([x - 3, y - 3, x + 3, y + 3], outline=color, width=2)


def _end(d, x, y, color):
    d.ellipse([x - 5, y - 5, x + 5, y + 5], outline=color, width=2)


def _dot(d, x, y, color):
    d.ellipse([x - 4, y - 4, x + 4, y + 4], fill=color)


def _cross(d, x, y, color, r):
    d.line([x - r, y - r, x + r, y + r], fill=color, width=3)
    d.line([x - r, y + r, x + r, y - r], fill=color, width=3)


def _path_symbol(color):
    def draw(d, x, y):
        d.line([x - 6, y, x + 6, y], fill=color, width=3)

    return draw


def _legend_entries(sim):
    """(name, how to draw its symbol at (x, y)) for each thing the picture shows."""
    w = sim.world
    entries = [(robot.name, _path_symbol(COLORS[i % len(COLORS)])) for i, robot in enumerate(sim.robots)]
    entries += [("start", lambda d, x, y: _start(d, x, y, BLACK)), ("end", lambda d, x, y: _end(d, x, y, BLACK))]
    if len(w.boxes):
        entries.append(("obstacle", lambda d, x, y: d.rectangle([x - 5, y - 5, x + 5, y + 5], fill=GREY)))
    if len(w.holes):
        entries.append(("hole", lambda d, x, y: d.rectangle([x - 5, y - 5, x + 5, y + 5], fill=DARK)))
    if w.station is not None:
        entries.append(
            (
                "charging station",
                lambda d, x, y: d.ellipse([x - 5, y - 5, x + 5, y + 5], outline=STATION, fill=STATION_FILL),
            )
        )
    if w.goal is not None:
        entries.append(("goal", lambda d, x, y: _cross(d, x, y, GOAL, 5)))
    if any(robot.collisions for robot in sim.robots):
        entries.append(("collision", lambda d, x, y: _dot(d, x, y, RED)))
    if any(robot.fell_at is not None for robot in sim.robots):
        entries.append(("fall", lambda d, x, y: _cross(d, x, y, MAGENTA, 5)))
    return entries


def title_of(sim, program="", timed=True):
    """The picture's title: the program, the world and (`timed`) the simulated time."""
    parts = ([program] if program else []) + [f"world {sim.world.name}"]
    return " - ".join(parts + ([f"{sim.time:.1f} s simulated"] if timed else []))


def render_png(sim, path, pixels_per_metre=None, max_pixels=1000, program=""):
    """Draw the world (walls, boxes, holes, goal, charging station), each robot's trajectory from
    its start (a square) to its end (a circle), collisions and falls, with a title (program, world,
    simulated time), a scale bar and a legend. Returns what the picture labels, in order."""
    canvas = _Canvas(sim, pixels_per_metre, max_pixels, title_of(sim, program))
    img = canvas.image
    d = ImageDraw.Draw(img)
    for i, robot in enumerate(sim.robots):
        color = COLORS[i % len(COLORS)]
        pts = [canvas.px(x, y) for _, x, y, _ in robot.trajectory[:: max(1, len(robot.trajectory) // 5000)]]
        pts.append(canvas.px(robot.x, robot.y))
        if len(pts) > 1:
            d.line(pts, fill=color, width=2)
        canvas.marks(d, robot, color)
        ex, ey = canvas.px(robot.x, robot.y)
        r = max(5.0, robot.spec.radius * canvas.scale)
        d.ellipse([ex - r, ey - r, ex + r, ey + r], outline=color, width=2)
    img.save(path)
    return canvas.labels


def render_gif(sim, path, fps=10.0, speed=None, max_frames=300, pixels_per_metre=None, max_pixels=500, program=""):
    """An animated GIF of the run: the world, each robot's trail so far, its disc and heading.

    Frames are taken every `speed / fps` simulated seconds (`speed`: simulated seconds per second of
    animation; default: the whole run fits in `max_frames` frames, and never slower than real time),
    shown `1 / fps` s each; the last frame holds the final state for a second. Each frame has the
    title, scale bar and legend of the PNG, and its time stamp in the title band, clear of the
    paths. Returns the path."""
    if fps <= 0 or max_frames < 1:
        raise ValueError("fps must be positive and max_frames at least 1")
    canvas = _Canvas(sim, pixels_per_metre, max_pixels, title_of(sim, program, timed=False))
    end = max((robot.trajectory[-1][0] for robot in sim.robots), default=0.0)
    end = max(end, sim.time)
    if speed is None:
        speed = max(1.0, end * fps / max_frames)
    dt = speed / fps
    count = min(max_frames, int(end / dt) + 1) if end > 0 else 1
    times = [min(end, i * dt) for i in range(count)]
    if times[-1] < end:
        times.append(end)
    # the trails are drawn incrementally on one layer; each frame copies it and adds the bodies
    layer = canvas.image.copy()
    trails = ImageDraw.Draw(layer)
    drawn = [1] * len(sim.robots)  # trajectory points already on the layer, per robot
    stamps = [[p[0] for p in robot.trajectory] for robot in sim.robots]
    palette = _palette(sim)
    frames = []
    for t in times:
        for i, robot in enumerate(sim.robots):
            n = _count_until(stamps[i], t)
            if n > drawn[i]:
                step = max(1, (n - drawn[i]) // 400)
                pts = [canvas.px(p[1], p[2]) for p in robot.trajectory[drawn[i] - 1 : n : step]]
                pts.append(canvas.px(*robot.trajectory[n - 1][1:3]))
                trails.line(pts, fill=COLORS[i % len(COLORS)], width=2)
                drawn[i] = n
        img = layer.copy()
        d = ImageDraw.Draw(img)
        for i, robot in enumerate(sim.robots):
            color = COLORS[i % len(COLORS)]
            canvas.marks(d, robot, color, until=t)
            _, x, y, theta = robot.trajectory[drawn[i] - 1]
            canvas.body(d, robot, x, y, theta, color)
        d.text((canvas.size[0] - MARGIN - 70, 5), f"t = {t:6.1f} s", fill=BLACK)
        frames.append(img.quantize(palette=palette, dither=Image.Dither.NONE))
    durations = [int(round(1000 / fps))] * len(frames)
    durations[-1] = max(durations[-1], 1000)
    frames[0].save(path, save_all=True, append_images=frames[1:], duration=durations, loop=0, optimize=False)
    return path


def _palette(sim):
    """A fixed palette holding every colour the pictures use (quantizing to it is fast and exact)."""
    colors = [
        (255, 255, 255),
        (0, 0, 0),
        (40, 40, 40),
        (150, 150, 150),
        (0, 170, 0),
        (210, 255, 210),
        (220, 0, 0),
        (255, 0, 0),
        (255, 0, 255),
    ] + COLORS
    flat = [c for color in colors for c in color]
    palette = Image.new("P", (1, 1))
    palette.putpalette(flat + flat[-3:] * (256 - len(colors)))
    return palette


def _count_until(stamps, t):
    """How many trajectory points have a time <= t (binary search; at least one)."""
    lo, hi = 0, len(stamps)
    while lo < hi:
        mid = (lo + hi) // 2
        if stamps[mid] <= t:
            lo = mid + 1
        else:
            hi = mid
    return max(1, lo)
