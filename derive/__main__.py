"""`python -m derive ...`: the command line (derive.cli)."""
from derive.cli import main

main()
