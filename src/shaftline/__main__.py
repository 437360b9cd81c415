"""``python -m shaftline``: the same command line as the ``shaftline`` script (for an
environment whose scripts folder is not on the PATH)."""

from shaftline.cli import main

if __name__ == "__main__":
    main()
