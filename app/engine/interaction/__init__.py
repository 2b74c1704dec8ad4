"""Interaction targets: what an external actor touches, where, and along which path."""
