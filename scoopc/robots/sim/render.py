"""PNG rendering of a world and the robots' trajectories (pillow)."""
from PIL import Image, ImageDraw

COLORS = [(31, 119, 180), (255, 127, 14), (44, 160, 44), (148, 103, 189), (140, 86, 75), (23, 190, 207)]


def render_png(sim, path, pixels_per_metre=None, max_pixels=1000):
    """Draw walls, boxes, holes, goal, charging station, trajectories, collisions and falls; returns path."""
    w = sim.world
    scale = pixels_per_metre or max(20.0, min(200.0, max_pixels / max(w.width, w.height)))
    margin = 10
    W, H = int(w.width * scale) + 2 * margin, int(w.height * scale) + 2 * margin

    def px(x, y):
        return (margin + x * scale, H - margin - y * scale)

    img = Image.new("RGB", (W, H), (255, 255, 255))
    d = ImageDraw.Draw(img)
    for poly in w.holes:
        d.polygon([px(x, y) for x, y in poly], fill=(40, 40, 40))
    for x0, y0, x1, y1 in w.boxes:
        a, b = px(x0, y1), px(x1, y0)
        d.rectangle([a, b], fill=(150, 150, 150))
    for x0, y0, x1, y1 in w.segments:
        d.line([px(x0, y0), px(x1, y1)], fill=(0, 0, 0), width=2)
    if w.station is not None:
        cx, cy = px(*w.station)
        r = w.station_radius * scale
        d.ellipse([cx - r, cy - r, cx + r, cy + r], outline=(0, 170, 0), width=2, fill=(210, 255, 210))
    if w.goal is not None:
        gx, gy = px(*w.goal)
        d.line([gx - 6, gy - 6, gx + 6, gy + 6], fill=(220, 0, 0), width=3)
        d.line([gx - 6, gy + 6, gx + 6, gy - 6], fill=(220, 0, 0), width=3)
    for i, robot in enumerate(sim.robots):
        color = COLORS[i % len(COLORS)]
        pts = [px(x, y) for _, x, y, _ in robot.trajectory[:: max(1, len(robot.trajectory) // 5000)]]
        pts.append(px(robot.x, robot.y))
        if len(pts) > 1:
            d.line(pts, fill=color, width=2)
        sx, sy = px(*robot.spec.start[:2])
        d.rectangle([sx - 3, sy - 3, sx + 3, sy + 3], outline=color, width=2)
        ex, ey = px(robot.x, robot.y)
        r = robot.spec.radius * scale
        d.ellipse([ex - r, ey - r, ex + r, ey + r], outline=color, width=2)
        for _, cx, cy in robot.collisions:
            qx, qy = px(cx, cy)
            d.ellipse([qx - 4, qy - 4, qx + 4, qy + 4], fill=(255, 0, 0))
        if robot.fell_at is not None:
            qx, qy = px(*robot.fell_at[1:])
            d.line([qx - 8, qy - 8, qx + 8, qy + 8], fill=(255, 0, 255), width=3)
            d.line([qx - 8, qy + 8, qx + 8, qy - 8], fill=(255, 0, 255), width=3)
    img.save(path)
    return path
