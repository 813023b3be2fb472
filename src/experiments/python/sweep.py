"""Sweeps (to come)."""
