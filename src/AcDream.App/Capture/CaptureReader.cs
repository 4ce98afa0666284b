using System.IO.Compression;
using System.Text.Json;
using AcDream.Core.Physics;

namespace AcDream.App.Capture;

/// <summary>
/// Reads a capture (<see cref="CaptureJson"/>) whole and checks every line before anything is used: a line that is not
/// JSON, lacks a field, has a field of the wrong type or one it does not know, or names an unknown kind is refused with
/// a <see cref="CaptureFormatException"/> naming the line and the field (the first bad line's), and nothing is returned.
/// The lines are parsed on all cores.
/// </summary>
internal static partial class CaptureReader
{
    /// <summary>Reads a capture file; one whose first two bytes are gzip's magic (<c>1F 8B</c>) is decompressed first.</summary>
    /// <exception cref="CaptureFormatException">The file cannot be read, or a line is bad.</exception>
    public static (CaptureHeader Header, List<CaptureCall> Calls) ReadFile(string path)
    {
        string[] lines;
        try
        {
            using var file = new FileStream(path, FileMode.Open, FileAccess.Read, FileShare.Read);
            bool gzip = file.ReadByte() == 0x1F && file.ReadByte() == 0x8B;
            file.Position = 0;
            using Stream stream = gzip ? new GZipStream(file, CompressionMode.Decompress) : file;
            using var reader = new StreamReader(stream);
            lines = Lines(reader);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or ArgumentException or NotSupportedException or InvalidDataException)
        {
            throw new CaptureFormatException(0, "", $"{path}: cannot read the capture ({e.Message})");
        }

        return Parse(lines);
    }

    /// <summary>Reads a capture from text.</summary>
    /// <exception cref="CaptureFormatException">A line is bad.</exception>
    public static (CaptureHeader Header, List<CaptureCall> Calls) Read(TextReader reader) => Parse(Lines(reader));

    private static string[] Lines(TextReader reader)
    {
        var lines = new List<string>();
        for (string? line; (line = reader.ReadLine()) is not null;)
        {
            lines.Add(line);
        }

        return [.. lines];
    }

    private static (CaptureHeader Header, List<CaptureCall> Calls) Parse(string[] lines)
    {
        if (lines.Length == 0)
        {
            throw new CaptureFormatException(1, "", "the capture is empty: it has no header.");
        }

        CaptureHeader header = ParseLine(lines[0], 1, line => line.Header());
        var calls = new CaptureCall[lines.Length - 1];
        CaptureFormatException? first = null;
        object gate = new();
        Parallel.For(1, lines.Length, (i, loop) =>
        {
            try
            {
                calls[i - 1] = ParseLine(lines[i], i + 1, line => line.Call());
            }
            catch (CaptureFormatException e)
            {
                lock (gate)
                {
                    first = first is null || e.Line < first.Line ? e : first;
                }

                loop.Break(); // the lines before it are still read: the error named is the first bad line's
            }
        });
        return first is null ? (header, [.. calls]) : throw first;
    }

    private static T ParseLine<T>(string text, int number, Func<Line, T> parse)
    {
        JsonDocument document;
        try
        {
            document = JsonDocument.Parse(text);
        }
        catch (JsonException e)
        {
            throw new CaptureFormatException(number, "", $"not JSON (byte {e.BytePositionInLine + 1}): {e.Message}");
        }

        using (document)
        {
            if (document.RootElement.ValueKind != JsonValueKind.Object)
            {
                throw new CaptureFormatException(number, "", $"a line is a JSON object; this one is {document.RootElement.ValueKind}.");
            }

            return parse(new Line(number, document.RootElement));
        }
    }

    /// <summary>One line's object, read field by field; each error names the line and the field's path.</summary>
    private sealed partial class Line(int number, JsonElement root)
    {
        private readonly int _number = number;

        public CaptureHeader Header()
        {
            if (Text(root, "", "kind") != "header")
            {
                throw Error("kind", "the first line is the header: \"kind\" is \"header\".");
            }

            Known(root, "", "kind", "format", "version", "scene", "frame");

            if (Text(root, "", "format") != CaptureJson.Format)
            {
                throw Error("format", $"not \"{CaptureJson.Format}\": not an acdream capture.");
            }

            if (Long(root, "", "version") != CaptureJson.Version)
            {
                throw Error("version", $"this program reads version {CaptureJson.Version}.");
            }

            string scene = Text(root, "", "scene");
            string frame = Text(root, "", "frame");
            uint? centre = frame == "global" ? null : Hex(root, "", "frame");
            if (centre is uint c && (c & 0xFFFFu) != 0xFFFFu)
            {
                throw Error("frame", $"\"{frame}\" is not a landblock id (0xXXYYFFFF) nor \"global\".");
            }

            return new CaptureHeader(scene, centre);
        }

        public CaptureCall Call()
        {
            string kindName = Text(root, "", "kind");
            CaptureKind kind = CaptureJson.KindOf(kindName) ?? throw Error("kind", $"unknown kind \"{kindName}\".");
            CaptureCall call = kind switch
            {
                CaptureKind.AddMover => AddMover(),
                CaptureKind.MoveMover => MoveMover(),
                CaptureKind.SetState => SetState(),
                CaptureKind.Commit => Commit(),
                CaptureKind.Resolve => Resolve(),
                CaptureKind.Cast => Cast(),
                _ => Named(kind),
            };
            return call;
        }

        private CaptureCall Named(CaptureKind kind)
        {
            bool answered = kind is CaptureKind.RemoveMover or CaptureKind.RemoveMovers;
            Known(root, "", answered ? ["kind", "id", "answer"] : ["kind", "id"]);
            var call = new CaptureCall(kind) { Id = Hex(root, "", "id") };
            return kind switch
            {
                CaptureKind.RemoveMover => call with { Answer = new CaptureAnswer(Removed: Bool(root, "", "answer")) },
                CaptureKind.RemoveMovers => call with { Answer = new CaptureAnswer(Count: Int(root, "", "answer")) },
                _ => call,
            };
        }

        private CaptureCall AddMover()
        {
            Known(root, "", "kind", "id", "shape", "position", "cell", "orientation", "state");
            return Place(new CaptureCall(CaptureKind.AddMover) { Id = Hex(root, "", "id"), Shape = Shape(), State = State(root, "state") });
        }

        private CaptureCall MoveMover()
        {
            Known(root, "", "kind", "id", "position", "cell", "orientation");
            return Place(new CaptureCall(CaptureKind.MoveMover) { Id = Hex(root, "", "id") });
        }

        private CaptureCall SetState()
        {
            Known(root, "", "kind", "id", "state");
            return new CaptureCall(CaptureKind.SetState) { Id = Hex(root, "", "id"), State = State(root, "state") };
        }

        private CaptureCall Commit()
        {
            Known(root, "", "kind", "answer");
            return new CaptureCall(CaptureKind.Commit) { Answer = new CaptureAnswer(Commit: Long(root, "", "answer")) };
        }

        private CaptureCall Resolve()
        {
            Known(root, "", "kind", "request", "span", "answer");
            int span = Int(root, "", "span");
            if (span < 0 || span > 1024)
            {
                throw Error("span", $"{span} is not a span length of 0 to 1024.");
            }

            return new CaptureCall(CaptureKind.Resolve) { Move = MoveRequest(Get(root, "", "request")), Span = span, Answer = MoveAnswer(Get(root, "", "answer"), span) };
        }

        private CaptureCall Cast()
        {
            Known(root, "", "kind", "request", "answer");
            return new CaptureCall(CaptureKind.Cast) { Cast = CastRequest(Get(root, "", "request")), Answer = new CaptureAnswer(Hit: CastHit(Get(root, "", "answer"))) };
        }

        private CaptureCall Place(CaptureCall call) => call with
        {
            Position = Vector(root, "", "position"),
            CellId = Hex(root, "", "cell"),
            Orientation = Quaternion(root, "", "orientation"),
        };

        private CaptureShape Shape()
        {
            JsonElement shape = Get(root, "", "shape");
            Known(shape, "shape", "cylinder", "door");
            if (shape.TryGetProperty("cylinder", out _))
            {
                float[] size = Floats(shape, "shape", "cylinder", 2);
                return new CaptureShape(Checked("shape.cylinder", () => new MoverBody(size[0], size[1])), null);
            }

            JsonElement door = Get(shape, "shape", "door");
            return door.ValueKind == JsonValueKind.String
                ? new CaptureShape(null, door.GetString())
                : throw Error("shape.door", "a mover's shape is a cylinder or a door of the scene's world named by a string; the recorder could not name this one.");
        }
    }
}
