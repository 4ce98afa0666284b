using System.Numerics;
using System.Text.Json;
using AcDream.App.Movement;
using AcDream.Core.Physics;

namespace AcDream.App.Scenes;

// SceneReader, a scene's parts: its creatures, pointers, effects, body and legs.
internal static partial class SceneReader
{
    /// <summary>
    /// <c>"creatures"</c>: at most <see cref="MaxCreatures"/>, each <c>{ "at": [x, y], "wander": metres, "seed": n }</c>:
    /// <c>at</c> required, within <see cref="MaxStartDistance"/> of (96, 96) as the start; <c>wander</c> 0..<see cref="MaxWander"/>,
    /// default 0 (it stands); <c>seed</c> a whole number ≥ 0, default the creature's number (1 for the first).
    /// </summary>
    private static List<SceneCreature> ReadCreatures(Context context, JsonElement root)
    {
        var creatures = new List<SceneCreature>();
        if (!root.TryGetProperty("creatures", out JsonElement element))
        {
            return creatures;
        }

        if (element.ValueKind != JsonValueKind.Array || element.GetArrayLength() > MaxCreatures)
        {
            throw context.Error("creatures", element, $"must be an array of at most {MaxCreatures} creatures");
        }

        foreach (JsonElement creature in element.EnumerateArray())
        {
            string path = $"creatures[{creatures.Count}]";
            context.RequireObject(creature, path, CreatureFields);
            Vector2 at = context.RequirePoint(creature, "at", $"{path}.at");
            if (MathF.Abs(at.X - 96f) > MaxStartDistance || MathF.Abs(at.Y - 96f) > MaxStartDistance)
            {
                throw context.Error($"{path}.at", creature.GetProperty("at"), $"must be within {MaxStartDistance} m of the centre landblock's middle (96, 96)");
            }

            float wander = context.OptionalNumber(creature, "wander", $"{path}.wander", 0f, 0f, MaxWander);
            float seed = context.OptionalNumber(creature, "seed", $"{path}.seed", creatures.Count + 1, 0f, int.MaxValue);
            if (seed != MathF.Floor(seed))
            {
                throw context.Error($"{path}.seed", creature.GetProperty("seed"), "must be a whole number");
            }

            creatures.Add(new SceneCreature(at, wander, (int)Math.Min(seed, int.MaxValue)));
        }

        return creatures;
    }

    /// <summary>
    /// <c>"pointers"</c>: at most <see cref="MaxPointers"/>, each <c>{ "name": text, "afterLeg": n, "from": [x, y, z], "towards": [x, y, z] }</c>,
    /// all required: <c>afterLeg</c> a leg's number (1 to the number of legs); <c>from</c> within <see cref="MaxStartDistance"/>
    /// of (96, 96) along X and Y, as the start; <c>towards</c> another point.
    /// </summary>
    private static List<ScenePointer> ReadPointers(Context context, JsonElement root, int legCount)
    {
        var pointers = new List<ScenePointer>();
        if (!root.TryGetProperty("pointers", out JsonElement element))
        {
            return pointers;
        }

        if (element.ValueKind != JsonValueKind.Array || element.GetArrayLength() > MaxPointers)
        {
            throw context.Error("pointers", element, $"must be an array of at most {MaxPointers} pointer rays");
        }

        foreach (JsonElement pointer in element.EnumerateArray())
        {
            string path = $"pointers[{pointers.Count}]";
            context.RequireObject(pointer, path, PointerFields);
            string name = context.RequireString(pointer, "name", $"{path}.name");
            context.Require(pointer, "afterLeg", $"{path}.afterLeg");
            float leg = context.OptionalNumber(pointer, "afterLeg", $"{path}.afterLeg", 0f, 1f, legCount);
            if (leg != MathF.Floor(leg))
            {
                throw context.Error($"{path}.afterLeg", pointer.GetProperty("afterLeg"), "must be a whole number");
            }

            Vector3 from = context.RequirePoint3(pointer, "from", $"{path}.from");
            if (MathF.Abs(from.X - 96f) > MaxStartDistance || MathF.Abs(from.Y - 96f) > MaxStartDistance)
            {
                throw context.Error($"{path}.from", pointer.GetProperty("from"), $"must be within {MaxStartDistance} m of the centre landblock's middle (96, 96)");
            }

            Vector3 towards = context.RequirePoint3(pointer, "towards", $"{path}.towards");
            if (towards == from)
            {
                throw context.Error($"{path}.towards", pointer.GetProperty("towards"), "must differ from \"from\" (it gives the ray's direction)");
            }

            pointers.Add(new ScenePointer(name, (int)leg, from, towards));
        }

        return pointers;
    }

    /// <summary><c>"effects"</c>: <c>"literal"</c>, <c>"player"</c> (with the player's body), or an object naming each effect.</summary>
    private static MovementOptions ReadEffects(Context context, JsonElement element)
    {
        if (element.ValueKind == JsonValueKind.String)
        {
            return element.GetString() switch
            {
                "literal" => MovementOptions.Literal,
                "player" => MovementOptions.Player,
                _ => throw context.Error("effects", element, "must be \"literal\", \"player\" or an object of effects"),
            };
        }

        context.RequireObject(element, "effects", EffectFields);
        return new MovementOptions
        {
            StepDownHeight = element.TryGetProperty("stepDownHeight", out _) ? context.OptionalNumber(element, "stepDownHeight", "effects.stepDownHeight", 0f, 0f, 1000f) : null,
            WalkableSlope = context.OptionalBool(element, "walkableSlope", "effects.walkableSlope"),
            SweepStepLength = element.TryGetProperty("sweepStepLength", out _) ? context.OptionalNumber(element, "sweepStepLength", "effects.sweepStepLength", 1f, 0.01f, 100f) : null,
            DoorsOnly = context.OptionalBool(element, "doorsOnly", "effects.doorsOnly"),
            Vertical = context.OptionalBool(element, "vertical", "effects.vertical"),
            Footing = context.OptionalBool(element, "footing", "effects.footing"),
            EdgeSlide = context.OptionalBool(element, "edgeSlide", "effects.edgeSlide"),
            Body = element.TryGetProperty("body", out JsonElement body) ? ReadBody(context, body) : null,
        };
    }

    /// <summary>
    /// <c>"effects.body"</c>: <c>"player"</c> (<see cref="MoverBody.Player"/>), <c>null</c> (a point, as
    /// when it is absent), or <c>{ "radius": r, "height": h }</c> in metres, r in (0, <see cref="MaxBodyRadius"/>],
    /// h in (0, <see cref="MaxBodyHeight"/>].
    /// </summary>
    private static MoverBody? ReadBody(Context context, JsonElement element)
    {
        switch (element.ValueKind)
        {
            case JsonValueKind.Null:
                return null;
            case JsonValueKind.String when element.GetString() == "player":
                return MoverBody.Player;
            case JsonValueKind.Object:
                context.RequireObject(element, "effects.body", BodyFields);
                foreach (string field in BodyFields)
                {
                    context.Require(element, field, $"effects.body.{field}");
                }

                float radius = context.OptionalNumber(element, "radius", "effects.body.radius", 0f, float.Epsilon, MaxBodyRadius);
                float height = context.OptionalNumber(element, "height", "effects.body.height", 0f, float.Epsilon, MaxBodyHeight);
                return new MoverBody(radius, height);
            default:
                throw context.Error("effects.body", element, "must be \"player\", null (a point) or { \"radius\": metres, \"height\": metres }");
        }
    }

    private static SceneLeg ReadLeg(Context context, JsonElement leg, string path, List<string> doors)
    {
        context.RequireObject(leg, path, LegFields);
        string name = context.RequireString(leg, "name", $"{path}.name");
        string? open = ReadDoor("open"), close = ReadDoor("close");
        if (open is not null && close is not null)
        {
            throw context.Error(path, leg, "has \"open\" and \"close\"; a leg opens a door or closes one");
        }
        bool run = context.OptionalBool(leg, "run", $"{path}.run");
        bool backward = context.OptionalBool(leg, "backward", $"{path}.backward");
        bool jump = context.OptionalBool(leg, "jump", $"{path}.jump");
        float skill = context.OptionalNumber(leg, "jumpSkill", $"{path}.jumpSkill", PlayerMovementMode.DefaultJumpSkill, 0f, MaxJumpSkill);
        if (skill != MathF.Floor(skill))
        {
            throw context.Error($"{path}.jumpSkill", leg.GetProperty("jumpSkill"), "must be a whole number");
        }

        bool hasIntent = leg.TryGetProperty("forward", out _) || leg.TryGetProperty("strafe", out _) || leg.TryGetProperty("turn", out _);
        if (leg.TryGetProperty("to", out _))
        {
            if (hasIntent)
            {
                throw context.Error(path, leg, "has \"to\" and an intent (forward/strafe/turn); a leg is one or the other");
            }

            Vector2 to = context.RequirePoint(leg, "to", $"{path}.to");
            float limit = context.OptionalNumber(leg, "seconds", $"{path}.seconds", DefaultPointLegSeconds, float.Epsilon, MaxLegSeconds);
            return new SceneLeg(name, to, 0f, 0f, 0f, run, backward, limit, jump, (int)skill, open, close);
        }

        if (leg.TryGetProperty("backward", out JsonElement backwardElement))
        {
            throw context.Error($"{path}.backward", backwardElement, "applies only to a leg with \"to\" (use \"forward\": -1 here)");
        }

        if (!hasIntent)
        {
            throw context.Error(path, leg, "needs \"to\" (walk to a point) or at least one of \"forward\", \"strafe\", \"turn\"");
        }

        float forward = context.OptionalNumber(leg, "forward", $"{path}.forward", 0f, -1f, 1f);
        float strafe = context.OptionalNumber(leg, "strafe", $"{path}.strafe", 0f, -1f, 1f);
        float turn = context.OptionalNumber(leg, "turn", $"{path}.turn", 0f, -1f, 1f);
        if (!leg.TryGetProperty("seconds", out _))
        {
            throw context.Error($"{path}.seconds", leg, "is required for a leg without \"to\"");
        }

        float seconds = context.OptionalNumber(leg, "seconds", $"{path}.seconds", 0f, float.Epsilon, MaxLegSeconds);
        return new SceneLeg(name, null, forward, strafe, turn, run, false, seconds, jump, (int)skill, open, close);

        string? ReadDoor(string field)
        {
            if (!leg.TryGetProperty(field, out JsonElement door))
            {
                return null;
            }

            return door.ValueKind == JsonValueKind.String && doors.Contains(door.GetString()!)
                ? door.GetString()
                : throw context.Error($"{path}.{field}", door, $"must name one of the scene's \"doors\" ({(doors.Count > 0 ? string.Join(", ", doors.Select(d => $"\"{d}\"")) : "it lists none")})");
        }
    }
}
