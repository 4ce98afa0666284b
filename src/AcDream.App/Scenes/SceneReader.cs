using System.Numerics;
using System.Reflection;
using System.Text.Json;
using AcDream.App.World;
using AcDream.Core.Physics;

namespace AcDream.App.Scenes;

/// <summary>Reads scene files (JSON, <c>docs/scenes.md</c>), checking every field.</summary>
internal static partial class SceneReader
{
    /// <summary>Resource name of the embedded default scene (<c>Scenes/holtburg-walk.json</c>).</summary>
    public const string DefaultResource = "scenes/holtburg-walk.json";

    /// <summary>Default time limit of a point leg, seconds.</summary>
    public const float DefaultPointLegSeconds = 60f;

    /// <summary>Largest scene file read, bytes: 1 MiB.</summary>
    public const int MaxFileBytes = 1024 * 1024;

    /// <summary>Longest leg, seconds.</summary>
    public const float MaxLegSeconds = 600f;

    /// <summary>Largest jump skill a leg may give (the game's skills stay far below it).</summary>
    public const float MaxJumpSkill = 10_000f;

    /// <summary>How far a start may be from the centre landblock's middle (96, 96), metres, along X and along Y: the 3 × 3 landblocks around Holtburg and one more ring (the world is bigger, the walk is not).</summary>
    public const float MaxStartDistance = 2 * PhysicsConstants.LandblockSize;

    /// <summary>Most creatures a scene may have.</summary>
    public const int MaxCreatures = 256;

    /// <summary>Farthest a creature may wander from its home, metres.</summary>
    public const float MaxWander = 50f;

    /// <summary>Most pointer rays a scene may have.</summary>
    public const int MaxPointers = 64;

    private static readonly string[] SceneFields = ["name", "world", "objects", "start", "legs", "notes", "effects", "creatures", "doors", "pointers"];
    private static readonly string[] CreatureFields = ["at", "wander", "seed"];
    private static readonly string[] PointerFields = ["name", "afterLeg", "from", "towards"];
    /// <summary>Largest body radius a scene may give, metres.</summary>
    public const float MaxBodyRadius = 10f;

    /// <summary>Largest body height a scene may give, metres.</summary>
    public const float MaxBodyHeight = 100f;

    private static readonly string[] EffectFields = ["stepDownHeight", "walkableSlope", "sweepStepLength", "doorsOnly", "body", "vertical", "footing", "edgeSlide"];
    private static readonly string[] BodyFields = ["radius", "height"];
    private static readonly string[] StartFields = ["position", "heading"];
    private static readonly string[] LegFields = ["name", "to", "forward", "strafe", "turn", "run", "backward", "seconds", "jump", "jumpSkill", "open", "close"];

    /// <summary>The embedded default scene.</summary>
    public static Scene ReadDefault()
    {
        using Stream stream = Assembly.GetExecutingAssembly().GetManifestResourceStream(DefaultResource)
            ?? throw new InvalidOperationException($"the program lacks its embedded resource {DefaultResource}.");
        using var reader = new StreamReader(stream);
        return Parse(reader.ReadToEnd(), "embedded default (src/AcDream.App/Scenes/holtburg-walk.json)");
    }

    /// <summary>Reads a scene file of at most <see cref="MaxFileBytes"/>.</summary>
    /// <exception cref="SceneFormatException">The file cannot be read, is too large, or is not a valid scene.</exception>
    public static Scene ReadFile(string path)
    {
        string text;
        try
        {
            // Read at most one byte past the limit, whatever length the file reports (/dev/zero says 0).
            var bytes = new byte[MaxFileBytes + 1];
            int length = 0;
            using (var stream = new FileStream(path, FileMode.Open, FileAccess.Read, FileShare.Read, bufferSize: 1, FileOptions.SequentialScan))
            {
                for (int read; length < bytes.Length && (read = stream.Read(bytes, length, bytes.Length - length)) > 0;)
                {
                    length += read;
                }
            }

            if (length > MaxFileBytes)
            {
                throw new SceneFormatException($"{path}: the scene file is larger than {MaxFileBytes / (1024 * 1024)} MiB ({MaxFileBytes} bytes), the limit");
            }

            using var reader = new StreamReader(new MemoryStream(bytes, 0, length), detectEncodingFromByteOrderMarks: true);
            text = reader.ReadToEnd();
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or ArgumentException or NotSupportedException)
        {
            throw new SceneFormatException($"{path}: cannot read the scene file ({e.Message})");
        }

        return Parse(text, path);
    }

    /// <summary>Parses scene text; <paramref name="source"/> names it in errors.</summary>
    /// <exception cref="SceneFormatException">The text is not a valid scene.</exception>
    public static Scene Parse(string json, string source)
    {
        JsonDocument document;
        try
        {
            document = JsonDocument.Parse(json, new JsonDocumentOptions { CommentHandling = JsonCommentHandling.Skip, AllowTrailingCommas = true });
        }
        catch (JsonException e)
        {
            throw new SceneFormatException($"{source}: not valid JSON (line {e.LineNumber + 1}, byte {e.BytePositionInLine + 1}): {e.Message}");
        }

        using (document)
        {
            var context = new Context(source);
            JsonElement root = document.RootElement;
            context.RequireObject(root, "(top level)", SceneFields);
            string name = context.RequireString(root, "name", "name");
            JsonElement start = context.Require(root, "start", "start");
            context.RequireObject(start, "start", StartFields);
            Vector2 position = context.RequirePoint(start, "position", "start.position");
            if (MathF.Abs(position.X - 96f) > MaxStartDistance || MathF.Abs(position.Y - 96f) > MaxStartDistance)
            {
                throw context.Error("start.position", start.GetProperty("position"), $"must be within {MaxStartDistance} m of the centre landblock's middle (96, 96)");
            }

            float heading = context.OptionalNumber(start, "heading", "start.heading", 0f, -360f, 360f);
            MovementOptions effects = root.TryGetProperty("effects", out JsonElement effectsElement) ? ReadEffects(context, effectsElement) : default;
            string world = HoltburgWorld.Worlds.Holtburg;
            if (root.TryGetProperty("world", out JsonElement worldElement))
            {
                world = worldElement.ValueKind == JsonValueKind.String && worldElement.GetString() is HoltburgWorld.Worlds.Holtburg or HoltburgWorld.Worlds.Staircase
                    ? worldElement.GetString()!
                    : throw context.Error("world", worldElement, $"must be \"{HoltburgWorld.Worlds.Holtburg}\" or \"{HoltburgWorld.Worlds.Staircase}\"");
            }

            List<string> doors = ReadNames(context, root, "doors", HoltburgWorld.DoorSets, world, "door");
            JsonElement legsElement = context.Require(root, "legs", "legs");
            if (legsElement.ValueKind != JsonValueKind.Array || legsElement.GetArrayLength() == 0)
            {
                throw context.Error("legs", legsElement, "must be a non-empty array of legs");
            }

            var legs = new List<SceneLeg>();
            int index = 0;
            foreach (JsonElement leg in legsElement.EnumerateArray())
            {
                legs.Add(ReadLeg(context, leg, $"legs[{index++}]", doors));
            }

            var notes = new List<string>();
            if (root.TryGetProperty("notes", out JsonElement notesElement))
            {
                if (notesElement.ValueKind != JsonValueKind.Array)
                {
                    throw context.Error("notes", notesElement, "must be an array of strings");
                }

                int n = 0;
                foreach (JsonElement note in notesElement.EnumerateArray())
                {
                    notes.Add(note.ValueKind == JsonValueKind.String ? note.GetString()! : throw context.Error($"notes[{n}]", note, "must be a string"));
                    n++;
                }
            }


            List<string> objects = ReadNames(context, root, "objects", HoltburgWorld.ObjectSets, world, "object set");
            List<SceneCreature> creatures = ReadCreatures(context, root);
            List<ScenePointer> pointers = ReadPointers(context, root, legs.Count);
            return new Scene(name, source, position, heading, legs, notes, effects, world, objects, creatures, doors, pointers);
        }
    }

    /// <summary>
    /// A list of names of the world's sets (<c>"objects"</c>, <c>"doors"</c>; <paramref name="what"/> names one): each one of <paramref name="sets"/> whose
    /// world is <paramref name="world"/>, at most once; empty when the field is absent.
    /// </summary>
    private static List<string> ReadNames(Context context, JsonElement root, string field, IReadOnlyDictionary<string, string> sets, string world, string what)
    {
        var names = new List<string>();
        if (!root.TryGetProperty(field, out JsonElement element))
        {
            return names;
        }

        if (element.ValueKind != JsonValueKind.Array)
        {
            throw context.Error(field, element, $"must be an array of {what} names");
        }

        int n = 0;
        foreach (JsonElement set in element.EnumerateArray())
        {
            string? text = set.ValueKind == JsonValueKind.String ? set.GetString() : null;
            if (text is null || !sets.TryGetValue(text, out string? home) || home != world)
            {
                string allowed = string.Join(", ", sets.Where(s => s.Value == world).Select(s => $"\"{s.Key}\""));
                throw context.Error($"{field}[{n}]", set, $"must be one of the {world} world's {what}s ({(allowed.Length > 0 ? allowed : "it has none")})");
            }

            if (names.Contains(text))
            {
                throw context.Error($"{field}[{n}]", set, "is listed twice");
            }

            names.Add(text);
            n++;
        }

        return names;
    }
}
