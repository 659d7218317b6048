"""Passes on the IR of a stage's code, each `run(...) -> (result, count)`, in the order a stage
runs them: sections (feature and decided macros resolved), reach (only what the roots use), fields
(struct members nothing reads, and their stores), forward (calls of forwarding functions made to
their targets); fields and forward can leave functions nothing calls, so reach follows them again
until nothing changes (stage.py runs them so, and counts them for the record). They never mutate a node: they build new ones along the paths they change
(rewrite.py), memoised where library items recur request after request."""
