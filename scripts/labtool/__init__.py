"""Hitbox's lab tool: the one home of the lab rules (task markers, the lab list, grading)."""
