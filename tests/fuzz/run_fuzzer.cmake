# SPDX-License-Identifier: GPL-3.0-or-later
# Runs one fuzz target for a fixed number of inputs from a fresh working corpus, seeded from
# SEEDS (never written to). Fails on any crash, leak, sanitizer report or broken invariant.
#   cmake -DFUZZER=path -DSEEDS=dir -DWORK=dir -DRUNS=n [-DDICT=file] -P run_fuzzer.cmake
set(dict "")
if(DICT AND EXISTS ${DICT})
    set(dict -dict=${DICT})
endif()
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/corpus ${WORK}/artifacts)
execute_process(
    COMMAND ${FUZZER} -runs=${RUNS} -seed=1 -max_len=65536 -timeout=20
            -artifact_prefix=${WORK}/artifacts/ ${dict} ${WORK}/corpus ${SEEDS}
    RESULT_VARIABLE result)
if(NOT result EQUAL 0)
    message(FATAL_ERROR "${FUZZER} failed (${result}); the input is in ${WORK}/artifacts/")
endif()
