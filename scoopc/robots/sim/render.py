"""Pictures of a run (pillow): a PNG of the world and the robots' trajectories, and an animated GIF."""

import math

from PIL import Image, ImageDraw

COLORS = [(31, 119, 180), (255, 127, 14), (44, 160, 44), (148, 103, 189), (140, 86, 75), (23, 190, 207)]
MARGIN = 10


class _Canvas:
    """The world drawn once (floor, holes, boxes, walls, station, goal) and its coordinate transform."""

    def __init__(self, sim, pixels_per_metre=None, max_pixels=1000):
        w = sim.world
        self.scale = pixels_per_metre or max(20.0, min(200.0, max_pixels / max(w.width, w.height)))
        self.size = (int(w.width * self.scale) + 2 * MARGIN, int(w.height * self.scale) + 2 * MARGIN)
        self.image = Image.new("RGB", self.size, (255, 255, 255))
        d = ImageDraw.Draw(self.image)
        px = self.px
        for poly in w.holes:
            d.polygon([px(x, y) for x, y in poly], fill=(40, 40, 40))
        for x0, y0, x1, y1 in w.boxes:
            d.rectangle([px(x0, y1), px(x1, y0)], fill=(150, 150, 150))
        for x0, y0, x1, y1 in w.segments:
            d.line([px(x0, y0), px(x1, y1)], fill=(0, 0, 0), width=2)
        if w.station is not None:
            cx, cy = px(*w.station)
            r = w.station_radius * self.scale
            d.ellipse([cx - r, cy - r, cx + r, cy + r], outline=(0, 170, 0), width=2, fill=(210, 255, 210))
        if w.goal is not None:
            gx, gy = px(*w.goal)
            d.line([gx - 6, gy - 6, gx + 6, gy + 6], fill=(220, 0, 0), width=3)
            d.line([gx - 6, gy + 6, gx + 6, gy - 6], fill=(220, 0, 0), width=3)

    def px(self, x, y):
        return (MARGIN + x * self.scale, self.size[1] - MARGIN - y * self.scale)

    def marks(self, d, robot, color, until=math.inf):
        """Start square, collisions (red dots) and the fall (magenta cross) up to time `until`."""
        sx, sy = self.px(*robot.spec.start[:2])
        d.rectangle([sx - 3, sy - 3, sx + 3, sy + 3], outline=color, width=2)
        for t, cx, cy in robot.collisions:
            if t <= until:
                qx, qy = self.px(cx, cy)
                d.ellipse([qx - 4, qy - 4, qx + 4, qy + 4], fill=(255, 0, 0))
        if robot.fell_at is not None and robot.fell_at[0] <= until:
            qx, qy = self.px(*robot.fell_at[1:])
            d.line([qx - 8, qy - 8, qx + 8, qy + 8], fill=(255, 0, 255), width=3)
            d.line([qx - 8, qy + 8, qx + 8, qy - 8], fill=(255, 0, 255), width=3)

    def body(self, d, robot, x, y, theta, color):
        """The robot's disc and a heading line."""
        ex, ey = self.px(x, y)
        r = robot.spec.radius * self.scale
        d.ellipse([ex - r, ey - r, ex + r, ey + r], outline=color, width=2)
        hx, hy = self.px(x + robot.spec.radius * math.cos(theta), y + robot.spec.radius * math.sin(theta))
        d.line([ex, ey, hx, hy], fill=color, width=2)


def render_png(sim, path, pixels_per_metre=None, max_pixels=1000):
    """Draw walls, boxes, holes, goal, charging station, trajectories, collisions and falls; returns path."""
    canvas = _Canvas(sim, pixels_per_metre, max_pixels)
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
        r = robot.spec.radius * canvas.scale
        d.ellipse([ex - r, ey - r, ex + r, ey + r], outline=color, width=2)
    img.save(path)
    return path


def render_gif(sim, path, fps=10.0, speed=None, max_frames=300, pixels_per_metre=None, max_pixels=500):
    """An animated GIF of the run: the world, each robot's trail so far, its disc and heading.

    Frames are taken every `speed / fps` simulated seconds (`speed`: simulated seconds per second of
    animation; default: the whole run fits in `max_frames` frames, and never slower than real time),
    shown `1 / fps` s each; the last frame holds the final state for a second. Returns the path."""
    if fps <= 0 or max_frames < 1:
        raise ValueError("fps must be positive and max_frames at least 1")
    canvas = _Canvas(sim, pixels_per_metre, max_pixels)
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
        d.text((MARGIN + 4, MARGIN + 4), f"t = {t:6.1f} s", fill=(0, 0, 0))
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
