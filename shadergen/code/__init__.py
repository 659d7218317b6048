"""Shader code as a typed IR (ir.py): library sources parsed and checked once per library, the
generator's own code built in it, passes run on it, targets print it."""
