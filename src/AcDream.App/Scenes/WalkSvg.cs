using System.Globalization;
using System.Numerics;
using System.Xml.Linq;
using AcDream.App.Movement;
using AcDream.App.World;
using AcDream.Core.Dat;
using AcDream.Core.Physics;

namespace AcDream.App.Scenes;

/// <summary>
/// Draws a walk as SVG: a top-down map (terrain contours every 2 m, the Holtburg floor plans, the
/// route coloured by cell, refused moves as red rings, and, with a body, the body's clearance where
/// it touched a wall; the scene's doors and its creatures' paths; the chase camera's eye) and a side profile of Z over
/// the frames (the feet's and the eye's).
/// </summary>
internal static partial class WalkSvg
{
    private const float Width = 1000f;
    private const float Margin = 40f;
    private const float MapMaxHeight = 620f;
    private const float ProfileHeight = 220f;
    private const float ContourInterval = 2f;

    /// <summary>Colour of the objects' footprints: purple, apart from the cells' hues, the route's greys, the red rings and the blue circles.</summary>
    private const string ObjectColour = "#8e24aa";

    /// <summary>Stroke of the body's clearance circles: blue, apart from the route's cell colours and the red refusal rings.</summary>
    private const string ClearanceColour = "#1565c0";

    /// <summary>Colour of the creatures' paths and bodies: brown, apart from the route's cell colours, the objects' purple and the blue circles.</summary>
    private const string CreatureColour = "#8d6e63";

    /// <summary>Colour of the doors' slabs: dark orange.</summary>
    private const string DoorColour = "#e65100";

    /// <summary>Colour of the chase camera's eye: cyan, apart from the route's cell colours and greys, the objects' purple, the creatures' brown and the blue circles.</summary>
    private const string EyeColour = "#00acc1";

    /// <summary>The eye's path is drawn through points at least this far apart, metres (and its last).</summary>
    private const float EyePathSpacing = 0.1f;

    /// <summary>A creature's path is drawn through points at least this far apart, metres (and its last), so a long walk stays a light line.</summary>
    private const float CreaturePathSpacing = 0.25f;

    /// <summary>A physics polygon is drawn as a wall outline when its unit normal's |Z| is below this (within about 11.5° of vertical). Drawing only; floors come from the engine.</summary>
    private const float WallMaxNormalZ = 0.2f;
    private static readonly XNamespace Svg = "http://www.w3.org/2000/svg";

    /// <summary>The SVG document for <paramref name="record"/>.</summary>
    public static XDocument Build(WalkRecord record, HoltburgWorld world)
    {
        IReadOnlyList<FrameSample> samples = record.Samples;
        Dictionary<uint, string> colours = Colours(record);

        // The scene's world frame, centred on Holtburg as the scene runner's engine: only its id and frame helpers are used.
        var frame = new PhysicsEngine(world.Center);

        // Map extent: the route and the creatures' paths, padded, in world metres (the engine's frame: 0xA9B4's SW corner is (0, 0)).
        Vector3[] drawn = [.. samples.Select(s => s.Position), .. record.Creatures.SelectMany(c => c.Samples).Select(s => s.Position)];
        // Padded by a tenth of the larger span, 3 to 15 m: a walk over a village keeps its 15 m, one up a stair is framed on it.
        float pad = Math.Clamp(0.1f * MathF.Max(drawn.Max(p => p.X) - drawn.Min(p => p.X), drawn.Max(p => p.Y) - drawn.Min(p => p.Y)), 3f, 15f);
        float minX = drawn.Min(p => p.X) - pad, maxX = drawn.Max(p => p.X) + pad;
        float minY = drawn.Min(p => p.Y) - pad, maxY = drawn.Max(p => p.Y) + pad;
        float scale = MathF.Min((Width - (2 * Margin)) / (maxX - minX), MapMaxHeight / (maxY - minY));
        float mapHeight = (maxY - minY) * scale;
        float mapTop = Margin;
        Vector2 Map(float x, float y) => new(Margin + ((x - minX) * scale), mapTop + ((maxY - y) * scale));

        var map = new XElement(Svg + "g", new XAttribute("id", "map"));
        map.Add(new XElement(Svg + "rect", Attr("x", Margin), Attr("y", mapTop), Attr("width", (maxX - minX) * scale), Attr("height", mapHeight), new XAttribute("fill", "#f4f1e8"), new XAttribute("stroke", "#999")));
        AddContours(map, world, frame, new MapExtent(minX, maxX, minY, maxY), Map);
        AddFloorPlans(map, world, frame, colours, Map);
        AddObjects(map, world, frame, scale, Map);
        AddDoors(map, record, world, Map);
        AddDoorRings(map, record, world, Map);
        AddCreatures(map, record, scale, Map);
        map.Add(EyePath(samples, s => Map(s.Camera.Eye.X, s.Camera.Eye.Y), s => new Vector2(s.Camera.Eye.X, s.Camera.Eye.Y)));
        map.Add(Sights(samples, Map));
        AddRoute(map, samples, colours, s => Map(s.Position.X, s.Position.Y));
        AddAirMarks(map, samples, s => Map(s.Position.X, s.Position.Y));
        foreach (Vector2 p in samples.Where(s => s.Refusal is not null).Select(s => Map(s.Position.X, s.Position.Y)).Distinct())
        {
            map.Add(new XElement(Svg + "circle", Attr("cx", p.X), Attr("cy", p.Y), Attr("r", 4f), new XAttribute("fill", "none"), new XAttribute("stroke", "#d00"), Attr("stroke-width", 1.5f)));
        }

        MoverBody? body = record.Scene.Effects.Body;
        if (body is not null)
        {
            map.Add(Clearance(samples, body.Value.Radius * scale, s => Map(s.Position.X, s.Position.Y)));
        }

        Vector2 start = Map(samples[0].Position.X, samples[0].Position.Y), end = Map(record.Final.Position.X, record.Final.Position.Y);
        map.Add(Label(start.X + 5, start.Y - 5, "start", 12));
        map.Add(Label(end.X + 5, end.Y + 14, "end", 12));
        map.Add(Label(Margin, mapTop - 8, Invariant($"{record.Scene.Name}: top-down, north up, {ScaleText(scale)}; contours every {ContourInterval} m; red rings: refused moves{(body is null ? "" : "; blue circles: the body at walls")}"), 13));
        map.Add(ScaleBar(Margin + 10f, mapTop + mapHeight - 12f, scale));

        // The inset: the objects at a scale where the rooms show.
        XElement? inset = Inset(record, world, frame, (colours, scale), mapTop + mapHeight + 50f, out float insetHeight);
        float insetBottom = inset is null ? mapTop + mapHeight : mapTop + mapHeight + 50f + insetHeight;

        // Profile: Z over frames.
        float profileTop = insetBottom + 60f;
        float minZ = samples.Min(s => MathF.Min(s.Position.Z, s.Camera.Eye.Z)) - 1f, maxZ = samples.Max(s => MathF.Max(s.Position.Z, s.Camera.Eye.Z)) + 1f;
        int frames = Math.Max(1, record.Final.Frame);
        Vector2 Profile(int frame, float z) => new(Margin + (frame * (Width - (2 * Margin)) / frames), profileTop + ((maxZ - z) * ProfileHeight / (maxZ - minZ)));
        var profile = new XElement(Svg + "g", new XAttribute("id", "profile"));
        profile.Add(new XElement(Svg + "rect", Attr("x", Margin), Attr("y", profileTop), Attr("width", Width - (2 * Margin)), Attr("height", ProfileHeight), new XAttribute("fill", "#fafafa"), new XAttribute("stroke", "#999")));
        float zStep = NiceStep((maxZ - minZ) / 6f);
        for (float z = MathF.Ceiling(minZ / zStep) * zStep; z <= maxZ; z += zStep)
        {
            Vector2 a = Profile(0, z), b = Profile(frames, z);
            profile.Add(Line(a, b, "#ddd", 1f));
            profile.Add(Label(4, a.Y + 4, Invariant($"{z:0.#}"), 10));
        }

        foreach (LegResult leg in record.Legs)
        {
            Vector2 a = Profile(leg.FirstFrame - 1, maxZ), b = Profile(leg.FirstFrame - 1, minZ);
            profile.Add(Line(a, b, "#ccc", 0.5f));
        }

        profile.Add(EyePath(samples, s => Profile(s.Frame, s.Camera.Eye.Z), null));
        AddRoute(profile, samples, colours, s => Profile(s.Frame, s.Position.Z));
        profile.Add(Label(Margin, profileTop - 8, Invariant($"Z (m) over frames 0..{frames} at {SceneRunner.FramesPerSecond} Hz; grey lines: leg starts; cyan: the camera's eye"), 13));

        // Legend: indoor cells.
        float legendTop = profileTop + ProfileHeight + 30f;
        var legend = new XElement(Svg + "g", new XAttribute("id", "legend"));
        float lx = Margin, ly = legendTop;
        foreach ((uint cell, string colour) in colours.Where(c => CellIds.IsIndoor(c.Key)))
        {
            legend.Add(new XElement(Svg + "rect", Attr("x", lx), Attr("y", ly - 9), Attr("width", 10f), Attr("height", 10f), new XAttribute("fill", colour)));
            legend.Add(Label(lx + 14, ly, $"0x{cell:X8} {HoltburgWorld.CellName(cell)}", 11));
            lx += 300f;
            if (lx > Width - 300f)
            {
                lx = Margin;
                ly += 16f;
            }
        }

        legend.Add(Label(lx, ly, "outdoor cells: alternating greys", 11));
        if (world.ObjectSurfaces.Count > 0)
        {
            ly += 18f;
            legend.Add(new XElement(Svg + "rect", Attr("x", Margin), Attr("y", ly - 9), Attr("width", 10f), Attr("height", 10f), new XAttribute("fill", ObjectColour), Attr("fill-opacity", 0.3f), new XAttribute("stroke", ObjectColour), new XAttribute("stroke-dasharray", "2,1")));
            legend.Add(Label(Margin + 14, ly, "objects, seen from above: floors filled, walls dashed, cylinders as circles", 11));
            ly += 16f;
            legend.Add(Label(Margin + 14, ly, Invariant($"objects ({string.Join(", ", world.ObjectSurfaces.Select(o => o.ObjectId).Distinct().Select(id => $"0x{id:X8}{(HoltburgWorld.ObjectName(id) is string n ? $" {n}" : "")}"))})"), 11));
        }

        if (record.DoorChanges.Count > 0)
        {
            ly += 18f;
            legend.Add(new XElement(Svg + "rect", Attr("x", Margin), Attr("y", ly - 7), Attr("width", 10f), Attr("height", 4f), new XAttribute("fill", DoorColour)));
            legend.Add(Label(Margin + 14, ly, Invariant($"doors, seen from above: their slabs, ringed on the map so they show at its scale ({string.Join(", ", record.DoorChanges.Select(d => d.DoorId).Distinct().Select(id => $"0x{id:X8}{(HoltburgWorld.ObjectName(id) is string n ? $" {n}" : "")}"))})"), 11));
        }

        if (record.Creatures.Count > 0)
        {
            ly += 18f;
            legend.Add(new XElement(Svg + "circle", Attr("cx", Margin + 5), Attr("cy", ly - 4), Attr("r", 4f), new XAttribute("fill", CreatureColour), Attr("fill-opacity", 0.3f), new XAttribute("stroke", CreatureColour)));
            legend.Add(Label(Margin + 14, ly, Invariant($"creatures ({record.Creatures.Count}): each one's path, and its body (radius {MoverBody.Player.Radius} m) where it ended"), 11));
        }

        ly += 18f;
        legend.Add(new XElement(Svg + "line", Attr("x1", Margin), Attr("y1", ly - 4), Attr("x2", Margin + 10), Attr("y2", ly - 4), new XAttribute("stroke", EyeColour), Attr("stroke-width", 1.5f)));
        legend.Add(Label(Margin + 14, ly, EyeLegend()[0], 11));
        ly += 14f;
        legend.Add(Label(Margin + 14, ly, EyeLegend()[1], 11));
        ly += 18f;
        legend.Add(new XElement(Svg + "polygon", new XAttribute("points", Invariant($"{Margin + 5},{ly - 10} {Margin},{ly - 1} {Margin + 10},{ly - 1}")), new XAttribute("fill", "#2e7d32")));
        legend.Add(new XElement(Svg + "polygon", new XAttribute("points", Invariant($"{Margin + 25},{ly} {Margin + 20},{ly - 9} {Margin + 30},{ly - 9}")), new XAttribute("fill", "#c62828")));
        legend.Add(Label(Margin + 34, ly, "jumps (where the frame took off) and landings (where it came down), on the map and the inset", 11));
        ly += 18f;
        legend.Add(new XElement(Svg + "circle", Attr("cx", Margin + 5), Attr("cy", ly - 4), Attr("r", 4f), new XAttribute("fill", "none"), new XAttribute("stroke", "#d00"), Attr("stroke-width", 1.5f)));
        legend.Add(Label(Margin + 14, ly, "refused move (the engine's outcome; the summary names it)", 11));
        if (body is not null)
        {
            ly += 16f;
            legend.Add(new XElement(Svg + "circle", Attr("cx", Margin + 5), Attr("cy", ly - 4), Attr("r", 4f), new XAttribute("fill", "none"), new XAttribute("stroke", ClearanceColour), Attr("stroke-width", 1f)));
            legend.Add(Label(Margin + 14, ly, Invariant($"body's clearance where it touched a wall: a circle of its radius ({body.Value.Radius} m) at each frame the engine answered Slid along a wall, or Wall"), 11));
        }

        float height = ly + 20f;

        var root = new XElement(Svg + "svg",
            new XAttribute("width", Invariant($"{Width}")),
            new XAttribute("height", Invariant($"{height:0}")),
            new XAttribute("viewBox", Invariant($"0 0 {Width} {height:0}")),
            new XAttribute("font-family", "sans-serif"),
            new XElement(Svg + "rect", Attr("x", 0f), Attr("y", 0f), new XAttribute("width", "100%"), new XAttribute("height", "100%"), new XAttribute("fill", "white")),
            map,
            inset,
            profile,
            legend);
        return new XDocument(new XDeclaration("1.0", "utf-8", null), root);
    }

    private static float NiceStep(float rough)
    {
        foreach (float step in new[] { 0.5f, 1f, 2f, 5f, 10f, 20f, 50f, 100f })
        {
            if (step >= rough)
            {
                return step;
            }
        }

        return 200f;
    }

    private static string ScaleText(float pixelsPerMetre) => Invariant($"{pixelsPerMetre:0.##} px per metre");

    private static XElement Line(Vector2 a, Vector2 b, string colour, float width) =>
        new(Svg + "line", Attr("x1", a.X), Attr("y1", a.Y), Attr("x2", b.X), Attr("y2", b.Y), new XAttribute("stroke", colour), Attr("stroke-width", width));

    private static XElement Label(float x, float y, string text, int size) =>
        new(Svg + "text", Attr("x", x), Attr("y", y), new XAttribute("font-size", size), text);

    private static XAttribute Attr(string name, float value) => new(name, value.ToString("0.##", CultureInfo.InvariantCulture));

    private static string Invariant(FormattableString text) => text.ToString(CultureInfo.InvariantCulture);
}
