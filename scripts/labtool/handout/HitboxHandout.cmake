# Written by the lab tool (scripts/lab.py handout): this tree is a student handout. The lab
# folders hold the student's own code, so each lab builds once: <lab> (the program) and <lab>_tests.
set(HITBOX_HANDOUT ON)
