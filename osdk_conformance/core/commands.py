"""Names of the commands of PROTOCOL-FACTS section 2, by (set, id): what
`command` and `ack_of` say in decoded stream events. Shared by every
decoder, so the names cannot drift apart."""

COMMANDS = {
    (0x00, 0x00): "version_query",
    (0x00, 0x01): "activation",
    (0x00, 0x10): "set_frequency",
    (0x01, 0x00): "control_authority",
    (0x01, 0x03): "movement_control",
    (0x02, 0x00): "broadcast",
    (0x02, 0x01): "lost_control",
}


def command_name(cmd_set: int, cmd_id: int) -> str:
    return COMMANDS.get((cmd_set, cmd_id), "unknown")


def ack_code_text(code: int) -> str:
    """An ACK code as messages show it: "0xFF01 not_activated". Construct's
    Enum gives the spec's name as a str subclass of the number; a code the
    spec does not name for that command arrives as an int and shows as hex only."""
    return f"0x{int(code):04X} {code}" if isinstance(code, str) else f"0x{int(code):04X}"
