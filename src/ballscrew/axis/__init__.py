"""The axis around the screw.

Motion profiles (:mod:`.motion`), torques, powers and energies over a cycle
(:mod:`.energy`), the temperature screw and nut reach (:mod:`.thermal`), an axis from
a case file with what it leaves out filled in and stated (:mod:`.setup`), the axis over
its duty for every model at once (:mod:`.duty`) and the whole axis check
(:mod:`.check`).
"""
