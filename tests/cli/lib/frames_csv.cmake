# Helpers for the cli tests that read an ig run's frames.csv (script mode).
# In tests/cli/lib so the tests' glob of tests/cli/*.cmake does not register it.

# Sets `var` to the sum of `column` over the frames of `csv`, leaving out
# the first `skip` frames.
function(sum_frames_column csv column skip var)
  file(STRINGS "${csv}" lines)
  list(GET lines 0 header)
  string(REPLACE "," ";" header "${header}")
  list(FIND header ${column} col)
  if(col LESS 0)
    message(FATAL_ERROR "${csv} has no column ${column}")
  endif()
  list(REMOVE_AT lines 0)
  if(skip GREATER 0)
    foreach(i RANGE 1 ${skip})
      list(REMOVE_AT lines 0)
    endforeach()
  endif()
  set(sum 0)
  foreach(line ${lines})
    string(REPLACE "," ";" cells "${line}")
    list(GET cells ${col} v)
    math(EXPR sum "${sum} + ${v}")
  endforeach()
  set(${var} ${sum} PARENT_SCOPE)
endfunction()

# Stops the test unless the header of `csv` matches `regex` (the columns a
# kind of run must log); `what` says which run.
function(expect_frames_columns csv regex what)
  file(STRINGS "${csv}" header LIMIT_COUNT 1)
  if(NOT header MATCHES "${regex}")
    message(FATAL_ERROR "frames.csv of ${what} lacks the columns ${regex}: ${header}")
  endif()
endfunction()
