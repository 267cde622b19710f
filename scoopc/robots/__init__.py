"""Roboscoop: robot library support (message model, transports, simulator)."""
