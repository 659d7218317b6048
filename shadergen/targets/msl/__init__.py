"""Metal Shading Language: the shared C-family printer (targets/cfamily) with MSL's syntax table
and an assembler of its own (target.py); no Metal compiler runs on Linux, so check.py
cross-checks its declarations against naga's MSL of our WGSL for the same material."""
