#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The tests' Python (tests/tests.cmake, BG_TEST_PYTHON): under ctest, `python3`
# is Debian's /usr/bin/python3 when there is one, whatever else comes first on
# the caller's PATH (a pyenv shim cost 0.4 s a call and lacked NumPy), and it
# has the packages tools/deps.sh --tests installs for the scripts.
# Usage: bash tests/tests_python.sh PATH_TO_BGDRAW   (from the project root)
set -u
. "$(dirname "$0")/lib/preamble.sh" "$@"
exe=$(python3 -c 'import os, sys; print(os.path.realpath(sys.executable))')
if [ -x /usr/bin/python3 ]; then
  [ "$exe" = "$(realpath /usr/bin/python3)" ]; cs_=$?
  check "python3 is Debian's /usr/bin/python3, not $exe" $cs_
fi
python3 -c 'import numpy, scipy.integrate, yaml'; check "python3 has NumPy, SciPy and PyYAML" $?
# a script's own `#!/usr/bin/env python3` finds the same interpreter
printf '#!/usr/bin/env python3\nimport os, sys\nprint(os.path.realpath(sys.executable))\n' >"$tmp/which.py"
chmod +x "$tmp/which.py"
[ "$("$tmp/which.py")" = "$exe" ]; check "#!/usr/bin/env python3 runs the same Python" $?
finish
