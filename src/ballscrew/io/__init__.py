"""Reading what users write.

Case files (:mod:`.case`) and their schema (:mod:`.schema`), screws by catalogue
designation or size (:mod:`.designation`), measured torque-speed curves
(:mod:`.measured`). Below the friction models: nothing here imports them.
"""
