"""Design rules: what the makers and the standards ask of a screw and its axis.

Load ratings and their plausibility (:mod:`.ratings`), life, static safety,
buckling, thermal lead error and the motor's inertia (:mod:`.sizing`), axial
stiffness, lost motion and eigenfrequency (:mod:`.stiffness`), speed limits
(:mod:`.limits`) and the makers' catalogue formulas for drag torque
(:mod:`.catalog_formulas`). They stand on the physics and below the contact state,
the models and the wings; nothing here computes friction.
"""
