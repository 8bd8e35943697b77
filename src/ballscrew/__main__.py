"""Run the command-line interface with ``python -m ballscrew``."""

from ballscrew.cli import main

if __name__ == "__main__":  # not when a tool imports every module (the docs' API reference)
    main()
