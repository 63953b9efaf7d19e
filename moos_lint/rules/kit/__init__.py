"""What every rule family uses: declaring a rule, selectors, suppression
comments, the glue to the C++ checks. Imports semantics and below.
"""
