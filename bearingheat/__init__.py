"""bearingheat: friction torque, power loss and thermal speed limits of shaft supports."""
__version__ = "0.1.0"
