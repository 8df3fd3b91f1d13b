#pragma once
// The --soak mode of the CIGI test host (cigi_soak_host.cpp): argv as
// cigi_query_host's, argv[4] == "--soak".
int soak_main(int argc, char** argv);
