"""scoopc: a compiler from Eiffel with SCOOP concurrency to Python, and its runtime."""

__version__ = "0.1.0"
