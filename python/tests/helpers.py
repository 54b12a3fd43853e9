"""Shared set-up of the Python tests: makes ``demill`` importable from the
source tree, and builds the small scenes the tests use."""

import math
import sys
from pathlib import Path

PYTHON_DIR = Path(__file__).resolve().parents[1]
REPO = PYTHON_DIR.parent
if str(PYTHON_DIR) not in sys.path:
    sys.path.insert(0, str(PYTHON_DIR))

import demill  # noqa: E402


def sphere_mass(radius, density):
    """m = 4/3 π r³ ρ."""
    return 4.0 / 3.0 * math.pi * radius ** 3 * density


def linear_world(dim=3, restitution=0.5, clamp=False, gravity=(0, 0, 0)):
    """A world of one material with a linear spring-dashpot model of exact
    restitution (unclamped by default: the classic model)."""
    w = demill.World(dim, gravity=gravity)
    m = w.material()
    w.pair(m, m, normal=demill.Normal.LINEAR, damping=demill.Damping.RESTITUTION,
           restitution=restitution, clamp_normal=clamp)
    return w, m


def linear_contact_time(k, mstar, e):
    """Duration of a linear spring-dashpot contact of restitution e:
    π / (ω √(1 - ξ²)), ξ = -ln e / √(π² + ln² e)."""
    xi = -math.log(e) / math.sqrt(math.pi ** 2 + math.log(e) ** 2)
    return math.pi / (math.sqrt(k / mstar) * math.sqrt(1 - xi * xi))
