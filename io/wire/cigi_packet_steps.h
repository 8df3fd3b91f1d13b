#pragma once
// The per-packet steps of the one walk over a CIGI host datagram
// (cigi_host_datagram.cpp). Each family of packets has a step that takes one
// framed packet of its opcodes (checking its size and fields, appending the
// decoded packet or a reject) and says whether the opcode was its.
// Internal to io/wire: consumers read CigiHostDatagram.

#include <cstddef>
#include <cstdint>

#include "io/wire/byte_io.h"
#include "io/wire/cigi_entities.h"
#include "io/wire/cigi_environment.h"
#include "io/wire/cigi_queries.h"
#include "io/wire/cigi_views.h"

namespace ig::io::wire::steps {

bool is_request_op(std::uint8_t op);
bool is_view_op(std::uint8_t op);
bool is_host_op(std::uint8_t op);
bool is_entity_op(std::uint8_t op);

// `p` points at the packet's opcode byte; `size` is its size byte (framed:
// within the datagram, not 0).
void take_request(std::uint8_t op, const std::uint8_t* p, std::size_t size, bytes::Order o,
                  const CigiRequestLimits& limits, CigiRequests& out);
void take_view(std::uint8_t op, const std::uint8_t* p, std::size_t size, bytes::Order o, CigiViewPackets& out);
void take_host(std::uint8_t op, const std::uint8_t* p, std::size_t size, bytes::Order o, CigiHostPackets& out);
void take_entity(std::uint8_t op, const std::uint8_t* p, std::size_t size, bytes::Order o, CigiEntityPackets& out);

}  // namespace ig::io::wire::steps
