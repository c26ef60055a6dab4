# Debian 12's Blender 3.4 glTF importer still names np.bool, which numpy 1.24 (Debian's) removed:
# the alias back, before any import. Imported by the scripts beside it.
import numpy

if "bool" not in numpy.__dict__:
    numpy.bool = bool
