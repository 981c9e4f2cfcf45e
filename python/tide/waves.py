"""tide.waves: linear (Airy) wave theory, as tide's wave makers use it."""
from ._tide.waves import flap_height_to_stroke, piston_height_to_stroke, ramp, wave_number

__all__ = ["wave_number", "piston_height_to_stroke", "flap_height_to_stroke", "ramp"]
