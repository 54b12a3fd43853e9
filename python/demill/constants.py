"""The constants of the C headers as :class:`enum.IntEnum` classes.

Written by hand from ``include/demill/*.h``; ``python/tests/test_constants.py``
parses the headers and checks every value, in both directions, so that the two
never drift apart.  Each class maps to a prefix of the C names: for example
``Status.INVALID_VALUE`` is ``DEMILL_ERR_INVALID_VALUE`` and
``WorldKey.TIME_STEP`` is ``DEMILL_WORLD_TIME_STEP`` (see :func:`c_name`).
"""

from enum import IntEnum, IntFlag

__all__ = ["VERSION_MAJOR", "VERSION_MINOR", "VERSION_PATCH", "VERSION_NUMBER",
           "VERSION_STRING", "ID_NONE", "Status", "Kind", "Integrator", "WorldKey",
           "MaterialKey", "Normal", "Damping", "Tangential", "Rolling", "Cohesion",
           "PairKey", "ParticleField", "IdField", "AddFlag", "WallField", "Caps", "Harmonic",
           "BodyAxis", "BodyFlag", "BodyField", "TemplateField", "ClumpField",
           "ContactField", "Energy", "DrumKey",
           "DrumPart", "LifterField", "Sizes", "Fill", "Region", "Spectrum"]

VERSION_MAJOR = 0
VERSION_MINOR = 1
VERSION_PATCH = 0
#: The version of the headers this binding was written against, encoded as
#: MAJOR * 10000 + MINOR * 100 + PATCH (``DEMILL_VERSION_NUMBER``).
VERSION_NUMBER = VERSION_MAJOR * 10000 + VERSION_MINOR * 100 + VERSION_PATCH
VERSION_STRING = f"{VERSION_MAJOR}.{VERSION_MINOR}.{VERSION_PATCH}"

#: ``DEMILL_ID_NONE``: never a valid id.
ID_NONE = 0


class Status(IntEnum):
    """Status codes (``DEMILL_OK``, ``DEMILL_ERR_*``)."""

    OK = 0
    NULL_POINTER = 1
    INVALID_VALUE = 2
    NOT_FINITE = 3
    UNKNOWN_KEY = 4
    INVALID_HANDLE = 5
    NO_CONTACT_MODEL = 6
    OVERLAP = 7
    OUT_OF_MEMORY = 8
    BUFFER_TOO_SMALL = 9
    READ_ONLY = 10
    DIMENSION = 11
    VERSION = 12
    UNSUPPORTED = 13
    UNSTABLE = 14
    IO = 15
    FORMAT = 16
    INTERRUPTED = 17
    LIMIT = 18


class Kind(IntEnum):
    """The kind of object an id names (``DEMILL_KIND_*``)."""

    NONE = 0
    MATERIAL = 1
    PARTICLE = 2
    WALL = 3
    DRUM = 4
    FEED = 5
    OUTLET = 6
    BODY = 7
    TEMPLATE = 8
    CLUMP = 9


class Integrator(IntEnum):
    """Values of ``WorldKey.INTEGRATOR`` (``DEMILL_INTEGRATOR_*``)."""

    VELOCITY_VERLET = 1
    SYMPLECTIC_EULER = 2
    ITERATIVE_REFINEMENT = 3


class WorldKey(IntEnum):
    """World parameter keys (``DEMILL_WORLD_*``); 150 and up are read-only."""

    TIME_STEP = 100
    GRAVITY_X = 101
    GRAVITY_Y = 102
    GRAVITY_Z = 103
    INTEGRATOR = 104
    SKIN = 105
    DISC_THICKNESS = 106
    ENERGY_TRACKING = 107
    TIME = 108
    THREADS = 109
    REFINE_TOLERANCE = 110
    REFINE_MAX_ITERATIONS = 111
    WATCHDOG = 112
    WATCHDOG_OVERLAP = 113
    WATCHDOG_INTERVAL = 114
    SINGLE_PRECISION = 115
    ORIENTATION_TRACKING = 116
    DIMENSION = 150
    STEP_COUNT = 151
    PARTICLE_COUNT = 152
    CONTACT_COUNT = 153
    WALL_CONTACT_COUNT = 154
    NEIGHBOUR_REBUILDS = 155
    REFINE_ITERATIONS = 156
    FORCE_EVALUATIONS = 157
    REFINE_UNCONVERGED = 158


class MaterialKey(IntEnum):
    """Material parameter keys (``DEMILL_MATERIAL_*``)."""

    DENSITY = 200
    YOUNGS_MODULUS = 201
    POISSON_RATIO = 202
    STIFFNESS = 203
    RESTITUTION = 204
    FRICTION = 205
    ROLLING_FRICTION = 206
    YIELD_STRESS = 207
    LOCAL_DAMPING = 210,
    RIGID = 212
    SURFACE_ENERGY = 213


class Normal(IntEnum):
    """Normal force laws, values of ``PairKey.NORMAL`` (``DEMILL_NORMAL_*``)."""

    NONE = 0
    LINEAR = 1
    HERTZ = 2
    THORNTON = 3
    WALTON_BRAUN = 4
    PLASTIC_PATHS = 5


class Damping(IntEnum):
    """Normal damping laws, values of ``PairKey.DAMPING`` (``DEMILL_DAMPING_*``)."""

    NONE = 0
    VISCOUS = 1
    RESTITUTION = 2


class Tangential(IntEnum):
    """Tangential laws, values of ``PairKey.TANGENTIAL`` (``DEMILL_TANGENTIAL_*``)."""

    NONE = 0
    COULOMB = 1
    SPRING = 2
    MINDLIN = 3


class Rolling(IntEnum):
    """Rolling resistance laws, values of ``PairKey.ROLLING`` (``DEMILL_ROLLING_*``)."""

    NONE = 0
    CONSTANT_TORQUE = 1
    SPRING = 2


class Cohesion(IntEnum):
    """Cohesion laws, values of ``PairKey.COHESION`` (``DEMILL_COHESION_*``)."""

    NONE = 0
    JKR = 1
    CAPILLARY = 2


class PairKey(IntEnum):
    """Material pair parameter keys (``DEMILL_PAIR_*``)."""

    NORMAL = 300
    DAMPING = 301
    TANGENTIAL = 302
    ROLLING = 303
    COHESION = 304
    RESTITUTION = 310
    FRICTION = 311
    ROLLING_FRICTION = 312
    NORMAL_STIFFNESS = 313
    VISCOUS_DAMPING = 314
    TANGENTIAL_STIFFNESS_RATIO = 315
    TANGENTIAL_DAMPING_FACTOR = 316
    COULOMB_REGULARISATION = 317
    ROLLING_REGULARISATION = 318
    CLAMP_NORMAL = 319
    YIELD_PRESSURE = 320
    PLASTIC_FIT_C0 = 321
    PLASTIC_FIT_C1 = 322
    PLASTIC_FIT_C2 = 323
    PLASTIC_FIT_EXPONENT = 324
    ROLLING_STIFFNESS = 327
    ROLLING_DAMPING_RATIO = 328,
    ADHESION_WORK = 331
    LIQUID_VOLUME = 332
    SURFACE_TENSION = 333
    CONTACT_ANGLE = 334


class ParticleField(IntEnum):
    """Particle fields of 1, 3 or 4 doubles (``DEMILL_PARTICLE_*``)."""

    POSITION = 1
    VELOCITY = 2
    ANGULAR_VELOCITY = 3
    RADIUS = 4
    MASS = 5
    FORCE = 6
    TORQUE = 7
    ANGLE = 8
    FIXED = 9
    ORIENTATION = 10


class IdField(IntEnum):
    """Id fields of particles (``DEMILL_PARTICLE_ID``, ``DEMILL_PARTICLE_MATERIAL``,
    ``DEMILL_PARTICLE_CLUMP``)."""

    ID = 100
    MATERIAL = 101
    CLUMP = 102


class AddFlag(IntFlag):
    """Flags of ``Particles.add`` (``DEMILL_ADD_*``)."""

    NO_OVERLAP = 1


class WallField(IntEnum):
    """Wall fields, 3 doubles each (``DEMILL_WALL_*``)."""

    POINT = 1
    NORMAL = 2
    CENTRE = 3
    VELOCITY = 4
    ANGULAR_VELOCITY = 5
    FORCE = 6
    TORQUE = 7
    SURFACE_VELOCITY = 8


class Caps(IntEnum):
    """Caps of a finite cylinder or cone (``DEMILL_CAPS_*``): START | END is BOTH."""

    NONE = 0
    START = 1
    END = 2
    BOTH = 3


class Harmonic(IntEnum):
    """Modes of a wall's harmonic motion (``DEMILL_HARMONIC_*``)."""

    TRANSLATION = 1
    ROTATION = 2


class BodyAxis(IntFlag):
    """Axes of a body, and bits of its free axes (``DEMILL_BODY_AXIS_*``)."""

    X = 1
    Y = 2
    Z = 4


class BodyFlag(IntFlag):
    """Flags of ``World.add_body`` (``DEMILL_BODY_NO_GRAVITY``)."""

    NO_GRAVITY = 1


class BodyField(IntEnum):
    """Body fields, 3 doubles each (``DEMILL_BODY_*``)."""

    POSITION = 1
    VELOCITY = 2
    FORCE_PARTICLES = 3
    FORCE_SPRING = 4
    FORCE_DAMPER = 5
    FORCE_EXTERNAL = 6


class TemplateField(IntEnum):
    """Clump template fields (``DEMILL_TEMPLATE_*``)."""

    MASS = 1
    VOLUME = 2
    CENTRE = 3
    PRINCIPAL_MOMENTS = 4
    PRINCIPAL_AXES = 5
    COUNT = 6
    MESH_VOLUME = 7
    FIT_VOLUME_ERROR = 8
    FIT_DEVIATION_OUT = 9
    FIT_DEVIATION_IN = 10
    FIT_CELL = 11


class ClumpField(IntEnum):
    """Clump fields (``DEMILL_CLUMP_*``)."""

    POSITION = 1
    ORIENTATION = 2
    VELOCITY = 3
    ANGULAR_VELOCITY = 4
    ANGULAR_MOMENTUM = 5
    FORCE = 6
    TORQUE = 7
    MASS = 8


class ContactField(IntEnum):
    """Contact fields (``DEMILL_CONTACT_*``)."""

    POINT = 1
    NORMAL = 2
    OVERLAP = 3
    NORMAL_FORCE = 4
    TANGENTIAL_FORCE = 5
    ROLLING_TORQUE = 6


class Energy(IntEnum):
    """Energy terms in J (``DEMILL_ENERGY_*``)."""

    KINETIC_TRANSLATIONAL = 1
    KINETIC_ROTATIONAL = 2
    POTENTIAL = 3
    ELASTIC_NORMAL = 4
    ELASTIC_TANGENTIAL = 5
    WALL_WORK = 6
    DISSIPATED_NORMAL = 7
    DISSIPATED_TANGENTIAL = 8
    DISSIPATED_FRICTION = 9
    DISSIPATED_ROLLING = 10
    DISSIPATED = 11
    TOTAL = 12
    FLOW = 13
    BODY_KINETIC = 14
    BODY_ELASTIC = 15
    BODY_POTENTIAL = 16
    BODY_DISSIPATED = 17
    BODY_WORK = 18
    DISSIPATED_PLASTIC = 19
    DISSIPATED_ROLLING_VISCOUS = 20
    DISSIPATED_LOCAL = 21
    COHESION = 22
    ELASTIC_ROLLING = 23


class DrumKey(IntEnum):
    """Drum parameters (400-449) and measurements (450-499) (``DEMILL_DRUM_*``)."""

    DIAMETER = 400
    LENGTH = 401
    LIFTERS = 402
    LIFTER_HEIGHT = 403
    LIFTER_WIDTH = 404
    LIFTER_FACE_ANGLE = 405
    LIFTER_PHASE = 406
    SPEED = 410
    SPEED_RPM = 411
    SPEED_FRACTION = 412
    RAMP_TIME = 413
    CRITICAL_DIAMETER = 414
    FILL_POROSITY = 415
    SAMPLE_INTERVAL = 416
    SHELL = 417
    CENTER_X = 418
    CENTER_Y = 419
    CENTER_Z = 420
    VELOCITY_X = 421
    VELOCITY_Y = 422
    VELOCITY_Z = 423
    VIBRATION_X = 424
    VIBRATION_Y = 425
    VIBRATION_Z = 426
    VIBRATION_FREQUENCY = 427
    VIBRATION_PHASE = 428
    CRITICAL_SPEED = 450
    CURRENT_SPEED = 451
    ANGLE = 452
    REVOLUTIONS = 453
    TORQUE = 454
    POWER = 455
    POWER_MEAN = 456
    POWER_CM = 457
    POWER_CM_MEAN = 458
    TOE_ANGLE = 459
    SHOULDER_ANGLE = 460
    COM_ANGLE = 461
    TOE_ANGLE_MEAN = 462
    SHOULDER_ANGLE_MEAN = 463
    COM_ANGLE_MEAN = 464
    ENERGY_IN = 465
    ENERGY_DISSIPATED = 466
    DISSIPATION_MEAN = 467
    LIFTER_COUNT = 468
    FORCE_X = 469
    FORCE_Y = 470
    FORCE_Z = 471
    CURRENT_VELOCITY_X = 472
    CURRENT_VELOCITY_Y = 473
    CURRENT_VELOCITY_Z = 474


class DrumPart(IntEnum):
    """Parts of the drum, each with a material (``DEMILL_DRUM_PART_*``)."""

    SHELL = 1
    CAPS = 2
    LIFTERS = 3


class LifterField(IntEnum):
    """Lifter fields (``DEMILL_LIFTER_*``)."""

    FORCE = 1
    FORCE_MEAN = 2
    FORCE_PEAK = 3
    ENERGY = 4
    ANGLE = 5


class Sizes(IntEnum):
    """Size distributions of ``Drum.fill`` (``DEMILL_SIZES_*``)."""

    CLASSES = 1
    ROSIN_RAMMLER = 2
    NORMAL = 3


class Fill(IntEnum):
    """What the target of ``Drum.fill`` means (``DEMILL_FILL_*``)."""

    COUNT = 1
    MASS = 2
    FRACTION = 3


class Region(IntEnum):
    """Kinds of region of ``World.fill_region``, feeds and outlets
    (``DEMILL_REGION_*``)."""

    BOX = 1
    CYLINDER = 2
    HALF_SPACE = 3
    DRUM = 4


class Spectrum(IntEnum):
    """Kinds of wall in the collision spectrum (``DEMILL_SPECTRUM_*``)."""

    SHELL = 0
    LIFTER = 1


#: Every enum class with the prefix of its C names.
C_PREFIXES = {
    Status: "DEMILL_ERR_",
    Kind: "DEMILL_KIND_",
    Integrator: "DEMILL_INTEGRATOR_",
    WorldKey: "DEMILL_WORLD_",
    MaterialKey: "DEMILL_MATERIAL_",
    Normal: "DEMILL_NORMAL_",
    Damping: "DEMILL_DAMPING_",
    Tangential: "DEMILL_TANGENTIAL_",
    Rolling: "DEMILL_ROLLING_",
    Cohesion: "DEMILL_COHESION_",
    PairKey: "DEMILL_PAIR_",
    ParticleField: "DEMILL_PARTICLE_",
    IdField: "DEMILL_PARTICLE_",
    AddFlag: "DEMILL_ADD_",
    WallField: "DEMILL_WALL_",
    BodyAxis: "DEMILL_BODY_AXIS_",
    BodyFlag: "DEMILL_BODY_",
    BodyField: "DEMILL_BODY_",
    TemplateField: "DEMILL_TEMPLATE_",
    ClumpField: "DEMILL_CLUMP_",
    Caps: "DEMILL_CAPS_",
    Harmonic: "DEMILL_HARMONIC_",
    ContactField: "DEMILL_CONTACT_",
    Energy: "DEMILL_ENERGY_",
    DrumKey: "DEMILL_DRUM_",
    DrumPart: "DEMILL_DRUM_PART_",
    LifterField: "DEMILL_LIFTER_",
    Sizes: "DEMILL_SIZES_",
    Fill: "DEMILL_FILL_",
    Region: "DEMILL_REGION_",
    Spectrum: "DEMILL_SPECTRUM_",
}


def c_name(member):
    """The C name of an enum member, e.g. ``DEMILL_WORLD_TIME_STEP``."""
    if member is Status.OK:
        return "DEMILL_OK"
    return C_PREFIXES[type(member)] + member.name
