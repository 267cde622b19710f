"""The numpy side of samples/scan_filter: a scan's ranges in, the nearest obstacle per sector out."""

import numpy as np

MEDIAN_WIDTH = 5  # beams: a spike narrower than half of this disappears


def median_filter(ranges):
    """Each beam replaced by the median of its MEDIAN_WIDTH neighbours (the scan wraps around)."""
    half = MEDIAN_WIDTH // 2
    padded = np.concatenate([ranges[-half:], ranges, ranges[:half]])
    windows = np.lib.stride_tricks.sliding_window_view(padded, MEDIAN_WIDTH)
    return np.median(windows, axis=1)


def nearest_by_sector(ranges, angle_min, increment, count):
    """The smallest filtered range in each of `count` sectors, the first centred straight ahead."""
    filtered = median_filter(np.asarray(ranges, dtype=float))
    angles = angle_min + increment * np.arange(len(filtered))
    width = 2 * np.pi / count
    sector = np.floor(((angles + width / 2) % (2 * np.pi)) / width).astype(int)
    nearest = np.full(count, np.inf)
    np.minimum.at(nearest, sector, filtered)
    return nearest
