using System.Numerics;
using System.Xml.Linq;
using AcDream.App.Movement;
using AcDream.App.World;
using AcDream.Core.Physics;

namespace AcDream.App.Scenes;

/// <summary>The inset (the scene's objects at a scale where rooms show), scale bars, and the marks on the route.</summary>
internal static partial class WalkSvg
{
    /// <summary>The inset's greatest height, pixels.</summary>
    private const float InsetMaxHeight = 380f;

    /// <summary>Metres of the world shown round the inset's route indoors (or its objects): enough for the rooms it went through.</summary>
    private const float InsetPadding = 6f;

    /// <summary>Seconds between the lines that join the player to the camera's eye on the map.</summary>
    private const float SightSeconds = 2f;

    /// <summary>
    /// The inset: the rooms the route went through (Holtburg's cottage and building B), or, for a route that stays
    /// outdoors, the scene's objects (the staircase's treads), framed with InsetPadding round them at the largest scale the panel allows, with the cells' floors, the objects, the doors, the route and
    /// its jump and landing marks and a scale bar; clipped to its frame. Its ids are prefixed <c>inset-</c>. Null when the
    /// scene has no objects, or when the map is within 1.5 times its scale.
    /// </summary>
    private static XElement? Inset(WalkRecord record, HoltburgWorld world, PhysicsEngine frame, (Dictionary<uint, string> Colours, float MapScale) map, float top, out float height)
    {
        height = 0f;
        Vector3[] corners = [.. record.Samples.Where(s => CellIds.IsIndoor(s.CellId)).Select(s => s.Position)];
        corners = corners.Length > 0 ? corners : [.. world.ObjectSurfaces.SelectMany(s => s.GetWalls().SelectMany(w => w.Outline)
            .Concat(s.GetFloorTriangles().SelectMany(t => new[] { t.A, t.B, t.C }))).Select(local => frame.ToWorld(world.Center, local))];
        if (corners.Length == 0)
        {
            return null;
        }

        float minX = corners.Min(p => p.X) - InsetPadding, maxX = corners.Max(p => p.X) + InsetPadding;
        float minY = corners.Min(p => p.Y) - InsetPadding, maxY = corners.Max(p => p.Y) + InsetPadding;
        float scale = MathF.Min((Width - (2 * Margin)) / (maxX - minX), InsetMaxHeight / (maxY - minY));
        if (scale < 1.5f * map.MapScale)
        {
            return null; // the map itself is as close (a scene framed on its stair)
        }

        Dictionary<uint, string> colours = map.Colours;
        height = (maxY - minY) * scale;
        float width = (maxX - minX) * scale;
        Vector2 Place(float x, float y) => new(Margin + ((x - minX) * scale), top + ((maxY - y) * scale));

        var inset = new XElement(Svg + "g", new XAttribute("id", "inset"), new XAttribute("clip-path", "url(#inset-clip)"));
        inset.Add(new XElement(Svg + "clipPath", new XAttribute("id", "inset-clip"),
            new XElement(Svg + "rect", Attr("x", Margin), Attr("y", top), Attr("width", width), Attr("height", height))));
        inset.Add(new XElement(Svg + "rect", Attr("x", Margin), Attr("y", top), Attr("width", width), Attr("height", height), new XAttribute("fill", "#f4f1e8"), new XAttribute("stroke", "#999")));
        AddFloorPlans(inset, world, frame, colours, Place);
        AddObjects(inset, world, frame, scale, Place);
        AddDoors(inset, record, world, Place);
        AddRoute(inset, record.Samples, colours, s => Place(s.Position.X, s.Position.Y));
        AddAirMarks(inset, record.Samples, s => Place(s.Position.X, s.Position.Y));
        foreach (XElement named in inset.Descendants().Where(e => e.Attribute("id") is not null && e.Name.LocalName != "clipPath"))
        {
            named.SetAttributeValue("id", "inset-" + (string)named.Attribute("id")!);
        }

        inset.Add(ScaleBar(Margin + 10f, top + height - 12f, scale));
        var panel = new XElement(Svg + "g", new XAttribute("id", "inset-panel"), inset,
            Label(Margin, top - 8, Invariant($"Closer: {(record.Samples.Any(s => CellIds.IsIndoor(s.CellId)) ? "the rooms the route went through" : "the objects")} and {InsetPadding} m round them, {ScaleText(scale)}; the route in its cells' colours, ▲ jumps, ▼ landings"), 13));
        return panel;
    }

    /// <summary>A scale bar at (<paramref name="x"/>, <paramref name="y"/>): a round length of about 100 px, labelled in metres.</summary>
    private static XElement ScaleBar(float x, float y, float pixelsPerMetre)
    {
        float metres = NiceStep(100f / pixelsPerMetre);
        float length = metres * pixelsPerMetre;
        return new XElement(Svg + "g", new XAttribute("class", "scale-bar"), new XAttribute("data-metres", Invariant($"{metres}")),
            Line(new Vector2(x, y), new Vector2(x + length, y), "#333", 2f),
            Line(new Vector2(x, y - 4), new Vector2(x, y + 4), "#333", 1.5f),
            Line(new Vector2(x + length, y - 4), new Vector2(x + length, y + 4), "#333", 1.5f),
            Label(x + length + 6, y + 4, Invariant($"{metres:0.#} m"), 11));
    }

    /// <summary>Jumps (▲, where the frame took off) and landings (▼, where it came down) on the route.</summary>
    private static void AddAirMarks(XElement parent, IReadOnlyList<FrameSample> samples, Func<FrameSample, Vector2> place)
    {
        var marks = new XElement(Svg + "g", new XAttribute("id", "air-marks"));
        foreach (FrameSample s in samples.Where(s => s.Moved.Jumps > 0 || s.Moved.Landings > 0))
        {
            Vector2 p = place(s);
            bool jump = s.Moved.Jumps > 0;
            string points = jump
                ? Invariant($"{p.X:0.##},{p.Y - 6:0.##} {p.X - 5:0.##},{p.Y + 3:0.##} {p.X + 5:0.##},{p.Y + 3:0.##}")
                : Invariant($"{p.X:0.##},{p.Y + 6:0.##} {p.X - 5:0.##},{p.Y - 3:0.##} {p.X + 5:0.##},{p.Y - 3:0.##}");
            marks.Add(new XElement(Svg + "polygon", new XAttribute("class", jump ? "jump" : "landing"), new XAttribute("points", points),
                new XAttribute("fill", jump ? "#2e7d32" : "#c62828"), Attr("fill-opacity", 0.8f),
                new XElement(Svg + "title", Invariant($"frame {s.Frame}: {(jump ? "jump" : "landing")} at ({s.Position.X:0.00}, {s.Position.Y:0.00}, {s.Position.Z:0.00})"))));
        }

        parent.Add(marks);
    }

    /// <summary>A ring of at least 7 px round each door that changed state, so a slab of a few centimetres shows on a map of a kilometre.</summary>
    private static void AddDoorRings(XElement parent, WalkRecord record, HoltburgWorld world, Func<float, float, Vector2> place)
    {
        foreach (WorldDoor door in world.Doors.Values.Where(d => record.DoorChanges.Any(c => c.DoorId == d.Id)))
        {
            Vector2 c = place(door.Position.X, door.Position.Y);
            parent.Add(new XElement(Svg + "circle", new XAttribute("class", "door-ring"), Attr("cx", c.X), Attr("cy", c.Y), Attr("r", 7f),
                new XAttribute("fill", "none"), new XAttribute("stroke", DoorColour), Attr("stroke-width", 2f)));
        }
    }

    /// <summary>Thin lines from the player to the camera's eye every <see cref="SightSeconds"/>: the boom that makes the eye's path.</summary>
    private static XElement Sights(IReadOnlyList<FrameSample> samples, Func<float, float, Vector2> place)
    {
        var sights = new XElement(Svg + "g", new XAttribute("id", "camera-sights"), new XAttribute("stroke", EyeColour), Attr("stroke-width", 0.75f), Attr("stroke-opacity", 0.7f));
        int every = (int)(SightSeconds * SceneRunner.FramesPerSecond);
        foreach (FrameSample s in samples.Where(s => s.Frame % every == 0 && s.Camera.Eye != default))
        {
            sights.Add(Line(place(s.Position.X, s.Position.Y), place(s.Camera.Eye.X, s.Camera.Eye.Y), EyeColour, 0.75f));
        }

        return sights;
    }

    /// <summary>The legend's lines for the camera's eye: what the cyan path and the lines to it are.</summary>
    private static string[] EyeLegend() =>
    [
        Invariant($"the chase camera's eye ({ChaseCamera.ViewerRadius} m sphere): it rides {ChaseCamera.BoomBack} m behind the player and {ChaseCamera.BoomUp} m over its head, pulled in where a wall is nearer;"),
        Invariant($"its path on the map, thin lines joining the player to it every {SightSeconds} s (the wedges are the boom swinging as the player turns); its Z in the profile"),
    ];
}
