"""Inverse orchestration: lab fits, coast-down fits, effect candidates, diagnose and audit."""
