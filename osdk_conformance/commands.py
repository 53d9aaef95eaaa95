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
