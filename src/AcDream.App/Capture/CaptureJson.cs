using System.Buffers;
using System.Globalization;
using System.Numerics;
using System.Text;
using System.Text.Json;
using AcDream.Core.Physics;

namespace AcDream.App.Capture;

/// <summary>
/// How a capture's lines are written (JSON Lines, <c>docs/capture.md</c>): a header, then one object per call with its
/// <c>"kind"</c>, its inputs and its <c>"answer"</c>. Every float is its IEEE bits, 8 hex digits (<c>"3F800000"</c> is 1),
/// every id and flag set <c>"0x"</c> and 8 hex digits, so a replay reads back exactly the bits written.
/// </summary>
internal static class CaptureJson
{
    /// <summary>The header's <c>"format"</c>.</summary>
    public const string Format = "acdream-capture";

    /// <summary>The header's <c>"version"</c>.</summary>
    public const int Version = 1;

    private static readonly string[] Kinds =
        ["addLandblock", "removeLandblock", "addMover", "moveMover", "setState", "open", "close", "removeMover", "removeMovers", "commit", "resolve", "cast"];

    /// <summary>The name of a kind in a line's <c>"kind"</c>.</summary>
    public static string KindName(CaptureKind kind) => Kinds[(int)kind];

    /// <summary>The kind a line's <c>"kind"</c> names, or null.</summary>
    public static CaptureKind? KindOf(string name)
    {
        int i = Array.IndexOf(Kinds, name);
        return i < 0 ? null : (CaptureKind)i;
    }

    /// <summary>A float's IEEE bits, 8 upper-case hex digits.</summary>
    public static string Bits(float value) => BitConverter.SingleToUInt32Bits(value).ToString("X8", CultureInfo.InvariantCulture);

    /// <summary>An id or a set of flags: <c>0x</c> and 8 upper-case hex digits.</summary>
    public static string Hex(uint value) => "0x" + value.ToString("X8", CultureInfo.InvariantCulture);

    /// <summary>One JSON line (no line break) written by <paramref name="write"/>.</summary>
    public static string Text(Action<Utf8JsonWriter> write)
    {
        var buffer = new ArrayBufferWriter<byte>(256);
        using (var writer = new Utf8JsonWriter(buffer))
        {
            write(writer);
        }

        return Encoding.UTF8.GetString(buffer.WrittenSpan);
    }

    /// <summary>The header line's object.</summary>
    public static void WriteHeader(Utf8JsonWriter w, CaptureHeader header)
    {
        w.WriteStartObject();
        w.WriteString("kind", "header");
        w.WriteString("format", Format);
        w.WriteNumber("version", Version);
        w.WriteString("scene", header.Scene);
        w.WriteString("frame", header.Centre is uint centre ? Hex(centre) : "global");
        w.WriteEndObject();
    }

    /// <summary>A call's line: its kind, its inputs and, for a kind that has one, its answer.</summary>
    public static void WriteCall(Utf8JsonWriter w, CaptureCall call)
    {
        w.WriteStartObject();
        WriteInputFields(w, call);
        if (call.Answer is CaptureAnswer answer)
        {
            w.WritePropertyName("answer");
            WriteAnswer(w, call.Kind, answer);
        }

        w.WriteEndObject();
    }

    /// <summary>A call's inputs alone, as one object (what a replay prints beside a difference).</summary>
    public static void WriteInputs(Utf8JsonWriter w, CaptureCall call)
    {
        w.WriteStartObject();
        WriteInputFields(w, call);
        w.WriteEndObject();
    }

    /// <summary>The answer of a call of <paramref name="kind"/>, as its line holds it.</summary>
    public static void WriteAnswer(Utf8JsonWriter w, CaptureKind kind, CaptureAnswer answer)
    {
        switch (kind)
        {
            case CaptureKind.RemoveMover:
                w.WriteBooleanValue(answer.Removed);
                break;
            case CaptureKind.RemoveMovers:
                w.WriteNumberValue(answer.Count);
                break;
            case CaptureKind.Commit:
                w.WriteNumberValue(answer.Commit);
                break;
            case CaptureKind.Resolve:
                WriteMoveResult(w, answer.Move, answer.Touched ?? []);
                break;
            case CaptureKind.Cast:
                WriteCastHit(w, answer.Hit);
                break;
            default:
                throw new ArgumentOutOfRangeException(nameof(kind), kind, "this kind of call has no answer.");
        }
    }

    private static void WriteInputFields(Utf8JsonWriter w, CaptureCall call)
    {
        w.WriteString("kind", KindName(call.Kind));
        switch (call.Kind)
        {
            case CaptureKind.AddMover:
                w.WriteString("id", Hex(call.Id));
                WriteShape(w, call.Shape!);
                WritePlace(w, call);
                WriteState(w, "state", call.State);
                break;
            case CaptureKind.MoveMover:
                w.WriteString("id", Hex(call.Id));
                WritePlace(w, call);
                break;
            case CaptureKind.SetState:
                w.WriteString("id", Hex(call.Id));
                WriteState(w, "state", call.State);
                break;
            case CaptureKind.Commit:
                break;
            case CaptureKind.Resolve:
                WriteMoveRequest(w, call.Move);
                w.WriteNumber("span", call.Span);
                break;
            case CaptureKind.Cast:
                WriteCastRequest(w, call.Cast);
                break;
            default: // the landblocks', open, close and the removals: an id
                w.WriteString("id", Hex(call.Id));
                break;
        }
    }

    private static void WriteShape(Utf8JsonWriter w, CaptureShape shape)
    {
        w.WriteStartObject("shape");
        if (shape.Cylinder is MoverBody body)
        {
            w.WriteStartArray("cylinder");
            w.WriteStringValue(Bits(body.Radius));
            w.WriteStringValue(Bits(body.Height));
            w.WriteEndArray();
        }
        else
        {
            w.WriteString("door", shape.Door);
        }

        w.WriteEndObject();
    }

    private static void WritePlace(Utf8JsonWriter w, CaptureCall call)
    {
        WriteVector(w, "position", call.Position);
        w.WriteString("cell", Hex(call.CellId));
        Quaternion q = call.Orientation;
        WriteFloats(w, "orientation", q.X, q.Y, q.Z, q.W);
    }

    private static void WriteState(Utf8JsonWriter w, string name, MoverState state)
    {
        w.WriteStartObject(name);
        w.WriteString("kind", state.Kind.ToString());
        w.WriteString("physics", Hex((uint)state.Physics));
        w.WriteString("description", Hex((uint)state.Description));
        w.WriteBoolean("ignoresCreatures", state.IgnoresCreatures);
        w.WriteEndObject();
    }

    private static void WriteMoveRequest(Utf8JsonWriter w, in MoveRequest request)
    {
        w.WriteStartObject("request");
        WriteVector(w, "position", request.Position);
        w.WriteString("cell", Hex(request.CellId));
        WriteVector(w, "delta", request.Delta);
        w.WriteString("step", Bits(request.StepUpHeight));
        MovementOptions o = request.Options;
        w.WriteStartObject("options");
        WriteOptionalFloat(w, "stepDown", o.StepDownHeight);
        w.WriteBoolean("walkableSlope", o.WalkableSlope);
        WriteOptionalFloat(w, "sweep", o.SweepStepLength);
        w.WriteBoolean("doorsOnly", o.DoorsOnly);
        if (o.Body is MoverBody body)
        {
            WriteFloats(w, "body", body.Radius, body.Height);
        }
        else
        {
            w.WriteNull("body");
        }

        w.WriteBoolean("vertical", o.Vertical);
        w.WriteBoolean("footing", o.Footing);
        w.WriteBoolean("edgeSlide", o.EdgeSlide);
        w.WriteEndObject();
        w.WriteString("mover", Hex(request.MoverId));
        w.WriteBoolean("report", request.WithReport);
        w.WriteEndObject();
    }

    private static void WriteMoveResult(Utf8JsonWriter w, in MoveResult result, uint[] touched)
    {
        ResolveResult a = result.Answer;
        w.WriteStartObject();
        WriteVector(w, "position", a.Position);
        w.WriteString("cell", Hex(a.CellId));
        w.WriteBoolean("onGround", a.IsOnGround);
        w.WriteString("outcome", a.Outcome.ToString());
        WriteVector(w, "normal", a.SurfaceNormal);
        WriteContact(w, "floor", result.Report.Floor);
        WriteContact(w, "wall", result.Report.Wall);
        w.WriteNumber("touchedCount", result.TouchedCount);
        w.WriteStartArray("touched");
        foreach (uint id in touched)
        {
            w.WriteStringValue(Hex(id));
        }

        w.WriteEndArray();
        w.WriteNumber("commit", result.Commit);
        w.WriteEndObject();
    }

    private static void WriteContact(Utf8JsonWriter w, string name, SurfaceContact contact)
    {
        w.WriteStartObject(name);
        w.WriteString("kind", contact.Kind.ToString());
        w.WriteString("id", Hex(contact.Id));
        WriteVector(w, "normal", contact.Normal);
        w.WriteEndObject();
    }

    private static void WriteCastRequest(Utf8JsonWriter w, in CastRequest request)
    {
        w.WriteStartObject("request");
        WriteVector(w, "from", request.From);
        w.WriteString("cell", Hex(request.FromCellId));
        WriteVector(w, "delta", request.Delta);
        w.WriteString("radius", Bits(request.Options.Radius));
        w.WriteString("filter", Hex((uint)request.Options.Filter));
        w.WriteString("mover", Hex(request.MoverId));
        w.WriteEndObject();
    }

    private static void WriteCastHit(Utf8JsonWriter w, in CastHit hit)
    {
        w.WriteStartObject();
        w.WriteBoolean("hit", hit.Hit);
        w.WriteString("fraction", Bits(hit.Fraction));
        WriteVector(w, "position", hit.Position);
        WriteVector(w, "point", hit.Point);
        WriteVector(w, "normal", hit.Normal);
        w.WriteString("kind", hit.Kind.ToString());
        w.WriteString("id", Hex(hit.Id));
        w.WriteString("cell", Hex(hit.CellId));
        w.WriteEndObject();
    }

    private static void WriteOptionalFloat(Utf8JsonWriter w, string name, float? value)
    {
        if (value is float v)
        {
            w.WriteString(name, Bits(v));
        }
        else
        {
            w.WriteNull(name);
        }
    }

    private static void WriteVector(Utf8JsonWriter w, string name, Vector3 v) => WriteFloats(w, name, v.X, v.Y, v.Z);

    private static void WriteFloats(Utf8JsonWriter w, string name, params ReadOnlySpan<float> values)
    {
        w.WriteStartArray(name);
        foreach (float value in values)
        {
            w.WriteStringValue(Bits(value));
        }

        w.WriteEndArray();
    }
}
