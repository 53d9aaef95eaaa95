"""The spec's tables this package's glue runs on (tools/libgen/python.py
renders them from spec/; do not edit)."""

SOF = ${sof}
HEADER_LEN = ${header_len}
CRC32_LEN = ${crc32_len}
MAX_LEN = ${max_len}
HEADER_ONLY_LEN = ${header_only_len}
# inclusive LEN ranges no frame can have
IMPOSSIBLE_LENGTHS = ${impossible_lengths}
# the receiver's header checks, in the order it makes them
HEADER_CHECKS = ${header_checks}
# header field -> (byte, lowest bit, width in bits), bit-endian le
${header_fields}
# the osdk_frame fields after the header
DATA_FIELD = ${data_field}
CRC32_FIELD = ${crc32_field}

# covers/stored_at: inclusive byte positions, negative from the end
CRC16 = ${crc16_params}
CRC32 = ${crc32_params}
CRC_CLASSES = ${crc_classes}
${crc16_table}
${crc32_table}

# the ksy field whose `valid` check fails -> its error class
${error_by_field}
# profile id -> OsdkPayload.Profile value
${profile_values}
# each profile's broadcast items in flag-bit order
${broadcast_items}
# Kaitai class of a broadcast layout -> {item: its flag field}
${item_flags}
# command name -> (cmd_set, cmd_id)
${commands}
# Kaitai class (qualified name) -> its ksy seq field ids, so /seq/N names a field
${seq}
SENT_COMMANDS = ${sent_names}
