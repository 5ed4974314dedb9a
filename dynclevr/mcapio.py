"""MCAP reading and writing: `dynclevr.*` channels as JSON (schemas in schemas/), Foxglove channels as protobuf.

Files are deterministic: log times come from simulation time, never the wall clock, and the writer's chunking and
compression are fixed. Every file carries a `dynclevr` metadata record naming its artifact schema and version.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any, Iterator

from mcap.exceptions import McapError
from zstandard import ZstdError
from mcap.reader import make_reader
from mcap.writer import CompressionType, Writer
from mcap_protobuf.decoder import DecoderFactory
from mcap_protobuf.schema import build_file_descriptor_set

from dynclevr import SCHEMA_DIR
from dynclevr.artifacts import ArtifactError, atomic_path, rerun_hint


# What a damaged file raises inside the mcap reader: its own errors, bad lengths, failed CRCs (ValueError),
# undecodable JSON or protobuf, a zstd chunk that does not decompress.
CORRUPT = (McapError, ValueError, EOFError, OSError, KeyError, ZstdError)


def frame_time_ns(frame: int, fps: int) -> int:
    return int(round(frame * 1e9 / fps))


def json_schema(name: str) -> bytes:
    """The JSON Schema of a `dynclevr.*` channel, from schemas/<name>.json."""
    path = SCHEMA_DIR / f"{name}.json"
    return path.read_bytes() if path.exists() else b"{}"


class McapOut:
    """Write one MCAP artifact atomically: `with McapOut(path, "dynclevr.scene4d", 1) as out: out.json(...)`."""

    def __init__(self, path: Path, artifact_schema: str, version: int, **meta: str):
        self.path = Path(path)
        self.meta = {"schema": artifact_schema, "version": str(version), **{k: str(v) for k, v in meta.items()}}
        self._channels: dict[str, int] = {}
        self._seq: dict[int, int] = {}

    def __enter__(self) -> "McapOut":
        self._atomic = atomic_path(self.path)
        tmp = self._atomic.__enter__()
        self._file = open(tmp, "wb")
        self._writer = Writer(self._file, compression=CompressionType.ZSTD, chunk_size=1 << 20)
        self._writer.start(profile="", library="dynclevr")
        self._writer.add_metadata("dynclevr", self.meta)
        return self

    def __exit__(self, exc_type, exc, tb):
        try:
            if exc_type is None:
                self._writer.finish()
        finally:
            self._file.close()
            self._atomic.__exit__(exc_type, exc, tb)
        return False

    def _channel(self, topic: str, schema_name: str, encoding: str, schema_data: bytes, msg_encoding: str) -> int:
        if topic not in self._channels:
            sid = self._writer.register_schema(name=schema_name, encoding=encoding, data=schema_data)
            self._channels[topic] = self._writer.register_channel(topic=topic, message_encoding=msg_encoding,
                                                                  schema_id=sid)
        return self._channels[topic]

    def _add(self, cid: int, t_ns: int, data: bytes) -> None:
        seq = self._seq.get(cid, 0)
        self._seq[cid] = seq + 1
        self._writer.add_message(channel_id=cid, log_time=t_ns, publish_time=t_ns, sequence=seq, data=data)

    def json(self, topic: str, schema_name: str, t_ns: int, message: Any) -> None:
        cid = self._channel(topic, schema_name, "jsonschema", json_schema(schema_name), "json")
        self._add(cid, t_ns, json.dumps(message, sort_keys=True, separators=(",", ":")).encode())

    def proto(self, topic: str, t_ns: int, message: Any) -> None:
        cls = type(message)
        cid = self._channel(topic, cls.DESCRIPTOR.full_name, "protobuf",
                            build_file_descriptor_set(cls).SerializeToString(), "protobuf")
        self._add(cid, t_ns, message.SerializeToString(deterministic=True))


class McapIn:
    """Read one MCAP artifact, checking its schema name and version first."""

    def __init__(self, path: Path, artifact_schema: str, version: int):
        self.path = Path(path)
        if not self.path.exists():
            raise ArtifactError(f"{self.path} is missing: {rerun_hint(self.path)}")
        try:
            with open(self.path, "rb") as f:
                meta = {m.name: m.metadata for m in make_reader(f).iter_metadata()}
        except CORRUPT as e:
            raise ArtifactError(f"{self.path} is not a readable MCAP file ({type(e).__name__}: {e}): "
                                f"{rerun_hint(self.path)}") from None
        m = meta.get("dynclevr", {})
        found = (m.get("schema", "?"), m.get("version", "?"))
        if found != (artifact_schema, str(version)):
            raise ArtifactError(f"{self.path} has schema {found[0]} v{found[1]}, expected {artifact_schema} "
                                f"v{version}: {rerun_hint(self.path)}")
        self.meta = m

    def messages(self, *topics: str) -> Iterator[tuple[str, int, Any]]:
        """Yield (topic, log_time_ns, decoded message): JSON as Python objects, protobuf as messages."""
        try:
            with open(self.path, "rb") as f:
                # Chunk CRCs: a damaged byte inside a frame's JPEG would otherwise decode into a plausible image.
                reader = make_reader(f, validate_crcs=True, decoder_factories=[DecoderFactory()])
                for schema, channel, message in reader.iter_messages(topics=list(topics) or None):
                    if channel.message_encoding == "json":
                        yield channel.topic, message.log_time, json.loads(message.data)
                    else:
                        yield channel.topic, message.log_time, _decode_proto(reader, schema, channel, message)
        except CORRUPT as e:
            raise ArtifactError(f"{self.path} is corrupt ({type(e).__name__}: {e}): "
                                f"{rerun_hint(self.path)}") from None

    def first(self, topic: str) -> Any:
        for _, _, msg in self.messages(topic):
            return msg
        raise ArtifactError(f"{self.path} has no '{topic}' channel: {rerun_hint(self.path)}")


_decoders: dict = {}


def _decode_proto(reader, schema, channel, message):
    key = schema.name if schema else None
    if key not in _decoders:
        _decoders[key] = DecoderFactory().decoder_for(channel.message_encoding, schema)
    return _decoders[key](message.data)
