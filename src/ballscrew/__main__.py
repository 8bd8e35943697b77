"""Run the command-line interface with ``python -m ballscrew``."""

from ballscrew.cli import main

main()
