# The sweep as a user runs it (included by CMakeLists.txt, whose rockfall_cli_test and
# variables it uses): crashes and --resume, shards and merge, the Slurm scripts, MPI ranks,
# replays and the files around a sweep.
# rockfall sweep: a crash in the middle of a batch then --resume stores exactly what an
# uninterrupted sweep stores (also with the --until rule), and the sweep's errors.
set(sweep_quick ${data}/scenarios/sweep_quick.toml)
set(sdb ${CMAKE_CURRENT_BINARY_DIR}/sweep)
add_test(NAME cli.sweep_resume_after_crash
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/sweep_resume.sh ${rockfall} ${sweep_quick} ${sdb}/resume)
add_test(NAME cli.sweep_until_resume_after_crash
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/sweep_resume.sh ${rockfall} ${sweep_quick} ${sdb}/until
        --until wall --half-width 0.1 --check-every 10 --samples 300)
# A cluster sweep (5 rocks a release): every rock's rows survive the crash and the resume,
# and --until counts a sample whose any rock reaches 0.27 m past the toe (8 of the first 10).
add_test(NAME cli.sweep_cluster_resume_after_crash
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/sweep_resume.sh ${rockfall}
        ${CMAKE_SOURCE_DIR}/tests/db/data/cluster_sweep.toml ${sdb}/cluster
        --samples 24 --until exceed:0.27 --half-width 0.2 --check-every 10)
set_tests_properties(cli.sweep_resume_after_crash cli.sweep_until_resume_after_crash
    cli.sweep_cluster_resume_after_crash PROPERTIES LABELS cli)
# `rockfall sweep --db FILE --resume` alone takes the scenario and every setting from the
# database: other seeds, sample counts, methods, stop rules and trajectory intervals than the
# defaults, for one-rock and cluster sweeps, equal an uninterrupted run's rows.
add_test(NAME cli.sweep_resume_stored_until
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/sweep_resume_stored.sh ${rockfall} ${sweep_quick}
        ${sdb}/stored_until --seed 11 --samples 120 --until wall --half-width 0.1
        --check-every 10 --trajectories 0.05)
add_test(NAME cli.sweep_resume_stored_lhs
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/sweep_resume_stored.sh ${rockfall} ${sweep_quick}
        ${sdb}/stored_lhs --method latin_hypercube --seed 5 --samples 30 --trajectories 0.1)
add_test(NAME cli.sweep_resume_stored_cluster
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/sweep_resume_stored.sh ${rockfall}
        ${CMAKE_SOURCE_DIR}/tests/db/data/cluster_sweep.toml ${sdb}/stored_cluster
        --seed 3 --samples 30 --until exceed:0.27 --half-width 0.1 --check-every 10)
set_tests_properties(cli.sweep_resume_stored_until cli.sweep_resume_stored_lhs
    cli.sweep_resume_stored_cluster PROPERTIES LABELS cli)
# Shards and merge (docs/cluster.md): three shards merged equal the one-process sweep, for a
# one-rock and a cluster sweep; merge's refusals; --shard's errors.
add_test(NAME cli.sweep_shards_merge
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/sweep_shards.sh ${rockfall} ${sweep_quick}
        ${sdb}/shards --samples 30 --seed 11 --trajectories 0.1)
add_test(NAME cli.sweep_shards_merge_cluster
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/sweep_shards.sh ${rockfall}
        ${CMAKE_SOURCE_DIR}/tests/db/data/cluster_sweep.toml ${sdb}/shards_cluster --samples 9 --seed 3)
set_tests_properties(cli.sweep_shards_merge cli.sweep_shards_merge_cluster PROPERTIES LABELS cli)
rockfall_cli_test(sweep_shard_k_too_large 2 "--shard 3/3: K \\(this shard's number\\) must be a whole number in \\[0, 2\\]"
    ${rockfall} sweep ${sweep_quick} --db ${sdb}/never.db --shard 3/3)
rockfall_cli_test(sweep_shard_no_shards 2 "--shard 0/0: N \\(the number of shards\\) must be a whole number in \\[1, 100000000\\]"
    ${rockfall} sweep ${sweep_quick} --db ${sdb}/never.db --shard 0/0)
rockfall_cli_test(sweep_shard_malformed 2 "--shard 2: must be K/N"
    ${rockfall} sweep ${sweep_quick} --db ${sdb}/never.db --shard 2)
rockfall_cli_test(sweep_shard_negative 2 "--shard -1/4: K"
    ${rockfall} sweep ${sweep_quick} --db ${sdb}/never.db --shard -1/4)
rockfall_cli_test(sweep_shard_until 2 "--until cannot be used with --shard 0/2: the stop rule is checked on the completed prefix"
    ${rockfall} sweep ${sweep_quick} --db ${sdb}/never.db --shard 0/2 --until wall)
rockfall_cli_test(merge_needs_shards 2 "shards is required"
    ${rockfall} merge ${sdb}/never.db)
# docs/cluster.md's Slurm job-array and merge scripts, extracted from the page and run as
# three array tasks (and a requeue), equal a one-process sweep.
add_test(NAME cli.cluster_job_array
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/cluster_job_array.sh ${rockfall}
        ${PROJECT_SOURCE_DIR}/docs/cluster.md ${sweep_quick} ${sdb}/job_array)
set_tests_properties(cli.cluster_job_array PROPERTIES LABELS cli)
# A sweep over 3 MPI ranks (docs/cluster.md) against one process: equal databases (one-rock,
# cluster, --until, a resume over ranks), signals and a killed rank, a refusal by rank 0.
if(MPI_C_FOUND)
    set(sweep_mpi ${CMAKE_CURRENT_SOURCE_DIR}/sweep_mpi.sh ${rockfall} ${MPIEXEC_EXECUTABLE})
    add_test(NAME cli.sweep_mpi_equal
        COMMAND ${sweep_mpi} ${sweep_quick} ${sdb}/mpi_equal equal --samples 40 --seed 5
            --trajectories 0.1)
    add_test(NAME cli.sweep_mpi_equal_cluster
        COMMAND ${sweep_mpi} ${CMAKE_SOURCE_DIR}/tests/db/data/cluster_sweep.toml
            ${sdb}/mpi_cluster equal --samples 9 --seed 3)
    add_test(NAME cli.sweep_mpi_until
        COMMAND ${sweep_mpi} ${sweep_quick} ${sdb}/mpi_until equal --samples 150 --until wall
            --half-width 0.1 --check-every 10)
    add_test(NAME cli.sweep_mpi_signals
        COMMAND ${sweep_mpi} ${sweep_quick} ${sdb}/mpi_signals signals --samples 150)
    add_test(NAME cli.sweep_mpi_refuse
        COMMAND ${sweep_mpi} ${sweep_quick} ${sdb}/mpi_refuse refuse --samples 5)
    set_tests_properties(cli.sweep_mpi_equal cli.sweep_mpi_equal_cluster cli.sweep_mpi_until
        cli.sweep_mpi_signals cli.sweep_mpi_refuse PROPERTIES LABELS "cli;mpi")
else()
    rockfall_cli_test(sweep_mpi_unavailable 1 "one of several MPI ranks .* built without MPI"
        env OMPI_COMM_WORLD_SIZE=3 ${rockfall} sweep ${sweep_quick} --db ${sdb}/never.db)
endif()
rockfall_cli_test(sweep_resume_needs_db 2 "--db is required"
    ${rockfall} sweep --resume)
rockfall_cli_test(sweep_resume_missing_db 2 "nope\\.db: no such file"
    ${rockfall} sweep --db nope.db --resume)
rockfall_cli_test(sweep_resume_not_a_db 2 "sweep_quick\\.toml is not an SQLite database"
    ${rockfall} sweep --db ${sweep_quick} --resume)
rockfall_cli_test(sweep_needs_scenario 2 "sweep needs a SCENARIO file. only `rockfall sweep --db FILE\\.db --resume`"
    ${rockfall} sweep --db ${sdb}/never.db)
rockfall_cli_test(sweep_resume_version1 2 "v1\\.db has schema version 1 .*does not add to it"
    sh -c "rm -f \"$1\" && sqlite3 \"$1\" <\"$2\" && \"$3\" sweep --db \"$1\" --resume"
    sh ${CMAKE_CURRENT_BINARY_DIR}/v1.db ${CMAKE_SOURCE_DIR}/tests/db/data/schema_v1.sql ${rockfall})
# A stored cluster release replays: every rock's reach, stop time and wall hits as stored.
rockfall_cli_test(simulate_replays_cluster_sample 0
    "5 rocks.*replay matches the database's stored outcome"
    sh -c "rm -rf \"$1\" && mkdir -p \"$1\" && \"$2\" sweep \"$3\" --db \"$1/c.db\" --samples 1 --quiet >/dev/null && \"$2\" simulate --from \"$1/c.db\" --sample 0 | tr '\\n' ' '"
    sh ${sdb}/cluster_replay ${rockfall} ${CMAKE_SOURCE_DIR}/tests/db/data/cluster_sweep.toml)
add_test(NAME cli.sweep_make_db COMMAND sh -c
    "rm -rf \"$1\" && mkdir -p \"$1\" && \"$2\" sweep \"$3\" --db \"$1/quick.db\" --quiet"
    sh ${sdb}/shared ${rockfall} ${sweep_quick})
set_tests_properties(cli.sweep_make_db PROPERTIES FIXTURES_SETUP sweep_db LABELS cli)
function(rockfall_sweep_test name code regex)
    rockfall_cli_test(${name} ${code} ${regex} ${ARGN})
    set_tests_properties(cli.${name} PROPERTIES FIXTURES_REQUIRED sweep_db)
endfunction()
set(quick_db ${sdb}/shared/quick.db)
rockfall_cli_test(sweep_help 0 "--until" ${rockfall} sweep --help)
rockfall_sweep_test(sweep_summary 0 "run: seed 7, monte_carlo, 40 of 40 samples, complete"
    ${rockfall} query ${quick_db} summary)
rockfall_sweep_test(sweep_refuses_existing_db 2 "quick\\.db.*exists"
    ${rockfall} sweep ${sweep_quick} --db ${quick_db} --quiet)
rockfall_sweep_test(sweep_resume_other_seed 2 "cannot resume: the database's seed is 7 but this command gives 8"
    ${rockfall} sweep ${sweep_quick} --db ${quick_db} --seed 8 --resume --quiet)
rockfall_sweep_test(sweep_resume_complete 0 "40 of 40 samples"
    ${rockfall} sweep ${sweep_quick} --db ${quick_db} --resume --quiet)
rockfall_sweep_test(sweep_resume_complete_alone 0 "quick\\.db: the run is complete already \\(40 samples stored\\). nothing to run.*40 of 40 samples"
    sh -c "\"$1\" sweep --db \"$2\" --resume --quiet 2>&1 | tr '\\n' ' '" sh ${rockfall} ${quick_db})
rockfall_sweep_test(sweep_resume_other_scenario 2
    "quick\\.db: cannot resume: the database's scenario and \\[sweep\\] hash is [0-9a-f]{16} but this command gives [0-9a-f]{16} \\(the scenario file or its \\[sweep\\] table changed\\)"
    ${rockfall} sweep ${data}/scenarios/sweep_mesh.toml --db ${quick_db} --resume --quiet)
rockfall_sweep_test(simulate_replays_sample 0 "replay matches the database's stored outcome"
    ${rockfall} simulate --from ${quick_db} --sample 17)
rockfall_sweep_test(simulate_from_missing_sample 2 "--sample 40: no such sample"
    ${rockfall} simulate --from ${quick_db} --sample 40)
# Seed 000's Fig. 5 from a real sweep (stations at 0 and 4 m): one legend entry per shape.
rockfall_sweep_test(query_stations_fig5 0 "^3$"
    sh -c "\"$1\" query \"$2\" stations --svg \"$3\" >/dev/null && grep -Ec '>(sphere|massive|planar) \\(n = [0-9]+\\)</text>' \"$3\""
    sh ${rockfall} ${quick_db} ${sdb}/fig5.svg)
rockfall_sweep_test(simulate_from_needs_sample 2 "needs --sample"
    ${rockfall} simulate --from ${quick_db})
rockfall_cli_test(sweep_lhs_until 2 "--until cannot be used with Latin hypercube"
    ${rockfall} sweep ${sweep_quick} --db ${sdb}/never.db --method lhs --until wall)
rockfall_cli_test(sweep_bad_until 2 "--until wal: must be wall or exceed:D"
    ${rockfall} sweep ${sweep_quick} --db ${sdb}/never.db --until wal)
rockfall_cli_test(sweep_bad_until_distance 2 "exceed: must be a number of m"
    ${rockfall} sweep ${sweep_quick} --db ${sdb}/never.db --until exceed:far)
rockfall_cli_test(sweep_unwritable_location 2 "/proc/rockfall\\.db"
    ${rockfall} sweep ${sweep_quick} --db /proc/rockfall.db --quiet)
add_test(NAME cli.sweep_mesh_rock_replays COMMAND ${expect} 0 "replay matches the database's stored outcome"
    sh -c "rm -f \"$1\"* && \"$2\" sweep \"$3\" --db \"$1\" --quiet >/dev/null && \"$2\" simulate --from \"$1\" --sample 3"
    sh ${sdb}/mesh.db ${rockfall} ${data}/scenarios/sweep_mesh.toml)
set_tests_properties(cli.sweep_mesh_rock_replays PROPERTIES LABELS cli)
# A sweep over catalogue entries and generated rocks of a target sphericity: every sample
# replays alone from the database bit for bit, and results break down by shape.
add_test(NAME cli.sweep_shapes_replay
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/sweep_shapes.sh ${rockfall}
        ${data}/scenarios/sweep_catalogue_quick.toml ${sdb}/shapes)
set_tests_properties(cli.sweep_shapes_replay PROPERTIES LABELS cli)
rockfall_cli_test(sweep_unknown_entry 2
    "sweep\\.rock\\.kind\\.choice\\[1\\] = \"boulder\": must be one of .*\"psi_0\\.72\".*sweep_bad_shapes\\.toml:6"
    ${rockfall} sweep ${data}/scenarios/sweep_bad_shapes.toml --db ${sdb}/never.db)
add_test(NAME cli.sweep_terrain_replays COMMAND ${expect} 0 "replay matches the database's stored outcome"
    sh -c "rm -f \"$1\"* && \"$2\" sweep \"$3\" --db \"$1\" --quiet >/dev/null && \"$2\" simulate --from \"$1\" --sample 2"
    sh ${CMAKE_CURRENT_BINARY_DIR}/terrain_sweep.db ${rockfall} ${data}/scenarios/sweep_terrain.toml)
set_tests_properties(cli.sweep_terrain_replays PROPERTIES LABELS cli)
add_test(NAME cli.sweep_interrupt_then_resume
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/sweep_interrupt.sh ${rockfall} ${sweep_quick} ${sdb}/interrupt)
set_tests_properties(cli.sweep_interrupt_then_resume PROPERTIES LABELS cli)
# The files around a sweep: a refused --resume changes no byte, a killed sweep's part file is
# explained and cleaned up, too many samples are refused before anything is written, and a
# reader left open at the end does not keep samples out of the .db.
add_test(NAME cli.sweep_files
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/sweep_files.sh ${rockfall} ${sweep_quick} ${sdb}/files)
add_test(NAME cli.sweep_reader_open
    COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/sweep_reader_open.sh ${rockfall} ${sweep_quick} ${sdb}/reader)
rockfall_cli_test(sweep_many_threads 0 "4 of 4 samples, complete"
    sh -c "rm -f \"$1\" && \"$2\" sweep \"$3\" --db \"$1\" --threads 1024 --samples 4 --quiet"
    sh ${CMAKE_CURRENT_BINARY_DIR}/threads.db ${rockfall} ${sweep_quick})
set_tests_properties(cli.sweep_files cli.sweep_reader_open PROPERTIES LABELS cli)
