# The sun in ig run's summary: from render.sun_direction, from
# environment.time_utc on generated and real terrain, and refused without a
# place. Expected values come from geometry, not from a previous run: at
# solar noon on the June solstice the sun stands 90 - lat + 23.44 deg high
# in the south.
set(IG_SUN_CHECK ${CMAKE_SOURCE_DIR}/tests/tools/sun_check.py)
set(IG_SUN_OUT ${CMAKE_BINARY_DIR}/test-out/sun)

# default.json's sun_direction [-0.5, 0.6, 0.45]: atan2(0.45, hypot(0.5, 0.6))
# = 29.949 deg up, azimuth atan2(-0.5, 0.6) = 320.194 deg (generated terrain:
# grid north is true north).
add_test(NAME cli.sun.summary_from_direction
  COMMAND bash -c "set -e; rm -rf '${IG_SUN_OUT}/direction'
    '$<TARGET_FILE:ig>' run '${CMAKE_SOURCE_DIR}/scenarios/default.json' --frames 1 --size 160x120 --out '${IG_SUN_OUT}/direction' --quiet
    python3 '${IG_SUN_CHECK}' check '${IG_SUN_OUT}/direction/summary.json' --elevation 29.949 --azimuth 320.194 --tolerance 0.001")
set_tests_properties(cli.sun.summary_from_direction PROPERTIES LABELS cli PASS_REGULAR_EXPRESSION "sun ok")

# default.json's first pose is 3.6 km north and 7.7 km east of its origin
# (46.5 N, 7.9 E): lat 46.532, lon 8.000, solar noon at 11:29:42 UTC
# (equation of time -1.7 min): 66.91 deg, due south.
add_test(NAME cli.sun.noon_on_generated_terrain
  COMMAND bash -c "set -e; rm -rf '${IG_SUN_OUT}/noon'; mkdir -p '${IG_SUN_OUT}'
    python3 '${IG_SUN_CHECK}' make '${CMAKE_SOURCE_DIR}/scenarios/default.json' '${IG_SUN_OUT}/noon.json' --time 2026-06-21T11:29:42Z
    '$<TARGET_FILE:ig>' run '${IG_SUN_OUT}/noon.json' --frames 1 --size 160x120 --out '${IG_SUN_OUT}/noon' --quiet
    python3 '${IG_SUN_CHECK}' check '${IG_SUN_OUT}/noon/summary.json' --elevation 66.91 --azimuth 180 --tolerance 0.3")
set_tests_properties(cli.sun.noon_on_generated_terrain PROPERTIES LABELS cli PASS_REGULAR_EXPRESSION "sun ok")

ig_cli_failure_test(cli.sun.time_without_place "environment.time_utc: the terrain .* has no georeference.*exit=[1-9]"
  "mkdir -p '${IG_SUN_OUT}' && python3 '${IG_SUN_CHECK}' make '${CMAKE_SOURCE_DIR}/scenarios/default.json' '${IG_SUN_OUT}/no_place.json' --time 2026-06-21T11:30:00Z --no-origin && '$<TARGET_FILE:ig>' run '${IG_SUN_OUT}/no_place.json' --frames 1 --size 160x120 --out '${IG_SUN_OUT}/no_place' --quiet")
ig_cli_failure_test(cli.sun.bad_time "environment.time_utc: must be in UTC.*exit=[1-9]"
  "mkdir -p '${IG_SUN_OUT}' && python3 '${IG_SUN_CHECK}' make '${CMAKE_SOURCE_DIR}/scenarios/default.json' '${IG_SUN_OUT}/bad_time.json' --time 2026-06-21T11:30:00+02:00 && '$<TARGET_FILE:ig>' run '${IG_SUN_OUT}/bad_time.json' --frames 1 --out '${IG_SUN_OUT}/bad_time' --quiet")

# Owens Valley (36.70 N, 118.06 W, the first pose) on the real DEM: solar
# noon near 19:54 UTC, 76.74 deg up.
ig_real_dem_test(cli.sun.noon_on_real_dem "real-DEM sun test"
  "set -e; rm -rf '${IG_SUN_OUT}/sierra'; mkdir -p '${IG_SUN_OUT}'
    python3 '${IG_SUN_CHECK}' make '${CMAKE_SOURCE_DIR}/scenarios/sierra_owens_valley.json' '${IG_SUN_OUT}/sierra.json' --time 2026-06-21T19:54:00Z
    '$<TARGET_FILE:ig>' run '${IG_SUN_OUT}/sierra.json' --frames 1 --size 160x120 --out '${IG_SUN_OUT}/sierra' --quiet
    python3 '${IG_SUN_CHECK}' check '${IG_SUN_OUT}/sierra/summary.json' --elevation 76.74 --azimuth 180 --tolerance 0.5"
  PASS_REGULAR_EXPRESSION "sun ok")
