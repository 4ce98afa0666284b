using System.Globalization;
using System.Numerics;
using System.Text;
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
        float minX = drawn.Min(p => p.X) - 15f, maxX = drawn.Max(p => p.X) + 15f;
        float minY = drawn.Min(p => p.Y) - 15f, maxY = drawn.Max(p => p.Y) + 15f;
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
        AddCreatures(map, record, scale, Map);
        map.Add(EyePath(samples, s => Map(s.Camera.Eye.X, s.Camera.Eye.Y), s => new Vector2(s.Camera.Eye.X, s.Camera.Eye.Y)));
        AddRoute(map, samples, colours, s => Map(s.Position.X, s.Position.Y));
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

        // Profile: Z over frames.
        float profileTop = mapTop + mapHeight + 60f;
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
            legend.Add(Label(Margin + 14, ly, Invariant($"doors, seen from above: their slabs ({string.Join(", ", record.DoorChanges.Select(d => d.DoorId).Distinct().Select(id => $"0x{id:X8}{(HoltburgWorld.ObjectName(id) is string n ? $" {n}" : "")}"))})"), 11));
        }

        if (record.Creatures.Count > 0)
        {
            ly += 18f;
            legend.Add(new XElement(Svg + "circle", Attr("cx", Margin + 5), Attr("cy", ly - 4), Attr("r", 4f), new XAttribute("fill", CreatureColour), Attr("fill-opacity", 0.3f), new XAttribute("stroke", CreatureColour)));
            legend.Add(Label(Margin + 14, ly, Invariant($"creatures ({record.Creatures.Count}): each one's path, and its body (radius {MoverBody.Player.Radius} m) where it ended"), 11));
        }

        ly += 18f;
        legend.Add(new XElement(Svg + "line", Attr("x1", Margin), Attr("y1", ly - 4), Attr("x2", Margin + 10), Attr("y2", ly - 4), new XAttribute("stroke", EyeColour), Attr("stroke-width", 1.5f)));
        legend.Add(Label(Margin + 14, ly, Invariant($"the chase camera's eye ({ChaseCamera.ViewerRadius} m sphere), beside the player's route: its path on the map, its Z in the profile"), 11));
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
            profile,
            legend);
        return new XDocument(new XDeclaration("1.0", "utf-8", null), root);
    }

    /// <summary>
    /// The body's clearance where it touched a wall: a circle of the body's radius (<paramref name="radius"/>,
    /// in pixels) around the feet at each frame the engine answered <see cref="ResolveOutcome.Slid"/>
    /// along a wall (a horizontal normal; a slide along a slope's contour touched no wall) or refused as
    /// <see cref="ResolveOutcome.Wall"/>. A frame whose circle would lie within a quarter of the radius of
    /// the last one drawn is left out, so a long slide is a row of circles, not a solid band.
    /// </summary>
    private static XElement Clearance(IReadOnlyList<FrameSample> samples, float radius, Func<FrameSample, Vector2> place)
    {
        var group = new XElement(Svg + "g", new XAttribute("id", "body-clearance"), new XAttribute("fill", "none"), new XAttribute("stroke", ClearanceColour), Attr("stroke-width", 0.6f));
        Vector2? last = null;
        foreach (FrameSample sample in samples)
        {
            bool touched = sample.Slide is Vector3 normal ? normal.Z == 0f : sample.Refusal == ResolveOutcome.Wall;
            Vector2 p = place(sample);
            if (touched && (last is not Vector2 previous || Vector2.Distance(p, previous) >= radius / 4f))
            {
                group.Add(new XElement(Svg + "circle", Attr("cx", p.X), Attr("cy", p.Y), Attr("r", radius), new XElement(Svg + "title", Invariant($"frame {sample.Frame}: ({sample.Position.X:F3}, {sample.Position.Y:F3})"))));
                last = p;
            }
        }

        return group;
    }

    /// <summary>
    /// The chase camera's eye (<see cref="FrameSample.Camera"/>) in <see cref="EyeColour"/>: one line through the frames'
    /// eyes, titled with the frames pulled in: on the map through those at least <see cref="EyePathSpacing"/> apart
    /// (<paramref name="ground"/>: where each is, metres) and the last; with no <paramref name="ground"/>, through every frame's.
    /// </summary>
    private static XElement EyePath(IReadOnlyList<FrameSample> samples, Func<FrameSample, Vector2> place, Func<FrameSample, Vector2>? ground)
    {
        var points = new StringBuilder();
        Vector2? last = null;
        for (int i = 0; i < samples.Count; i++)
        {
            Vector2 at = ground?.Invoke(samples[i]) ?? default;
            if (ground is null || last is not Vector2 previous || Vector2.Distance(at, previous) >= EyePathSpacing || i == samples.Count - 1)
            {
                Vector2 p = place(samples[i]);
                points.Append(Invariant($"{p.X:0.##},{p.Y:0.##} "));
                last = at;
            }
        }

        int pulled = samples.Count(s => s.Camera.PulledIn);
        return new XElement(Svg + "polyline", new XAttribute("class", "camera-eye"), new XAttribute("points", points.ToString().TrimEnd()),
            new XAttribute("fill", "none"), new XAttribute("stroke", EyeColour), Attr("stroke-width", 1f), Attr("stroke-opacity", 0.8f),
            new XElement(Svg + "title", Invariant($"the chase camera's eye: {samples.Count} frames, pulled in at {pulled}")));
    }

    /// <summary>Indoor cells get distinct hues in order of first visit; outdoor cells alternate two greys.</summary>
    private static Dictionary<uint, string> Colours(WalkRecord record)
    {
        var colours = new Dictionary<uint, string>();
        int indoor = 0, outdoor = 0;
        foreach ((int _, uint cell) in record.CellVisits())
        {
            if (colours.ContainsKey(cell))
            {
                continue;
            }

            colours[cell] = CellIds.IsIndoor(cell)
                ? Invariant($"hsl({(indoor++ * 137.508) % 360:0},75%,42%)")
                : (outdoor++ % 2 == 0 ? "#333333" : "#888888");
        }

        return colours;
    }

    private static void AddRoute(XElement parent, IReadOnlyList<FrameSample> samples, Dictionary<uint, string> colours, Func<FrameSample, Vector2> place)
    {
        int i = 0;
        while (i < samples.Count)
        {
            int j = i;
            while (j + 1 < samples.Count && samples[j + 1].CellId == samples[i].CellId)
            {
                j++;
            }

            // Each run starts at the previous run's last point, so the line has no gaps.
            var points = new StringBuilder();
            for (int k = Math.Max(0, i - 1); k <= j; k++)
            {
                Vector2 p = place(samples[k]);
                points.Append(Invariant($"{p.X:0.##},{p.Y:0.##} "));
            }

            parent.Add(new XElement(Svg + "polyline",
                new XAttribute("points", points.ToString().TrimEnd()),
                new XAttribute("fill", "none"),
                new XAttribute("stroke", colours[samples[i].CellId]),
                Attr("stroke-width", 2.5f),
                new XElement(Svg + "title", $"0x{samples[i].CellId:X8} {HoltburgWorld.CellName(samples[i].CellId)}".TrimEnd())));
            i = j + 1;
        }
    }

    /// <summary>
    /// The floors, in the cell's colour: the triangles the engine samples (<see cref="CellSurface.GetFloorTriangles"/>),
    /// so the map cannot disagree with the physics; then the walls as outlines (near-vertical physics polygons).
    /// </summary>
    private static void AddFloorPlans(XElement parent, HoltburgWorld world, PhysicsEngine frame, Dictionary<uint, string> colours, Func<float, float, Vector2> place)
    {
        string Points(uint cellId, IEnumerable<Vector3> landblockLocal) =>
            string.Join(" ", landblockLocal.Select(v => frame.ToWorld(cellId, v)).Select(p => place(p.X, p.Y)).Select(p => Invariant($"{p.X:0.##},{p.Y:0.##}")));

        var floors = new XElement(Svg + "g", new XAttribute("id", "floors"));
        foreach (CellSurface surface in world.CellSurfaces)
        {
            string fill = colours.TryGetValue(surface.CellId, out string? colour) ? colour : "#bbbbbb";
            foreach ((Vector3 a, Vector3 b, Vector3 c) in surface.GetFloorTriangles())
            {
                floors.Add(new XElement(Svg + "polygon", new XAttribute("points", Points(surface.CellId, [a, b, c])), new XAttribute("fill", fill), Attr("fill-opacity", 0.25f)));
            }
        }

        var plans = new XElement(Svg + "g", new XAttribute("id", "floor-plans"));
        foreach (var cell in world.Cells)
        {
            Frame position = cell.EnvCell.Position;
            foreach (Polygon polygon in cell.CellStruct.PhysicsPolygons.Values)
            {
                Vector3[] v = polygon.VertexIds.Select(id => position.Origin + Vector3.Transform(cell.CellStruct.VertexArray.Vertices[(ushort)id].Origin, position.Orientation)).ToArray();
                if (v.Length >= 3 && MathF.Abs(Vector3.Normalize(Vector3.Cross(v[1] - v[0], v[2] - v[0])).Z) < WallMaxNormalZ)
                {
                    plans.Add(new XElement(Svg + "polygon", new XAttribute("points", Points(cell.CellId, v)), new XAttribute("fill", "none"), new XAttribute("stroke", "#555"), Attr("stroke-width", 0.6f)));
                }
            }
        }

        parent.Add(floors);
        parent.Add(plans);
    }

    /// <summary>
    /// The objects' footprints, seen from above, in <see cref="ObjectColour"/>: their floors filled (the
    /// triangles the engine samples, <see cref="ObjectSurface.GetFloorTriangles"/>) and their walls as
    /// dashed outlines (<see cref="ObjectSurface.GetWalls"/>; a cylinder as a circle of its radius), one
    /// group per object titled with its id, so they read apart from the cells' solid grey walls.
    /// </summary>
    private static void AddObjects(XElement parent, HoltburgWorld world, PhysicsEngine frame, float scale, Func<float, float, Vector2> place)
    {
        var objects = new XElement(Svg + "g", new XAttribute("id", "objects"), new XAttribute("stroke", ObjectColour), new XAttribute("stroke-dasharray", "3,2"), Attr("stroke-width", 0.5f));
        foreach (ObjectSurface surface in world.ObjectSurfaces)
        {
            Vector2 Place(Vector3 local)
            {
                Vector3 p = frame.ToWorld(world.Center, local);
                return place(p.X, p.Y);
            }

            string Points(IEnumerable<Vector3> local) => string.Join(" ", local.Select(Place).Select(p => Invariant($"{p.X:0.##},{p.Y:0.##}")));
            string name = HoltburgWorld.ObjectName(surface.ObjectId) is string n ? $" {n}" : "";
            var group = new XElement(Svg + "g", new XAttribute("class", "object"), new XAttribute("data-object-id", $"0x{surface.ObjectId:X8}"),
                new XElement(Svg + "title", $"object 0x{surface.ObjectId:X8}{name}{(surface.IsBuilding ? " (building shell)" : "")}"));
            foreach (ObjectWallInfo wall in surface.GetWalls())
            {
                if (wall.Radius > 0f)
                {
                    Vector2 c = Place(wall.Outline[0]);
                    group.Add(new XElement(Svg + "circle", new XAttribute("class", "object-wall"), Attr("cx", c.X), Attr("cy", c.Y), Attr("r", wall.Radius * scale), new XAttribute("fill", "none")));
                }
                else
                {
                    group.Add(new XElement(Svg + "polygon", new XAttribute("class", "object-wall"), new XAttribute("points", Points(wall.Outline)), new XAttribute("fill", "none")));
                }
            }

            foreach ((Vector3 a, Vector3 b, Vector3 c) in surface.GetFloorTriangles())
            {
                group.Add(new XElement(Svg + "polygon", new XAttribute("class", "object-floor"), new XAttribute("points", Points([a, b, c])), new XAttribute("fill", ObjectColour), Attr("fill-opacity", 0.3f), new XAttribute("stroke", "none")));
            }

            objects.Add(group);
        }

        parent.Add(objects);
    }

    /// <summary>
    /// The scene's doors, seen from above, in <see cref="DoorColour"/>: each slab's physics polygons placed at the door's
    /// frame, one group per door titled with its id and its states (<see cref="WalkRecord.DoorChanges"/>).
    /// </summary>
    private static void AddDoors(XElement parent, WalkRecord record, HoltburgWorld world, Func<float, float, Vector2> place)
    {
        var doors = new XElement(Svg + "g", new XAttribute("id", "doors"), new XAttribute("fill", DoorColour), Attr("fill-opacity", 0.6f), new XAttribute("stroke", DoorColour), Attr("stroke-width", 0.5f));
        foreach (WorldDoor door in world.Doors.Values.Where(d => record.DoorChanges.Any(c => c.DoorId == d.Id)))
        {
            string states = string.Join(", ", record.DoorChanges.Where(c => c.DoorId == door.Id).Select(c => Invariant($"{c.State.ToString().ToLowerInvariant()} at frame {c.Frame}")));
            var group = new XElement(Svg + "g", new XAttribute("class", "door"), new XAttribute("data-mover-id", $"0x{door.Id:X8}"),
                new XElement(Svg + "title", $"door 0x{door.Id:X8} {HoltburgWorld.ObjectName(door.Id)}: {states}"));
            foreach (Polygon polygon in door.Slab.PhysicsPolygons.Values)
            {
                string points = string.Join(" ", polygon.VertexIds.Select(id => door.Position + Vector3.Transform(door.Slab.VertexArray.Vertices[(ushort)id].Origin, door.Orientation))
                    .Select(p => place(p.X, p.Y)).Select(p => Invariant($"{p.X:0.##},{p.Y:0.##}")));
                group.Add(new XElement(Svg + "polygon", new XAttribute("points", points)));
            }

            doors.Add(group);
        }

        parent.Add(doors);
    }

    /// <summary>
    /// The creatures, in <see cref="CreatureColour"/>: each one's path (through points <see cref="CreaturePathSpacing"/>
    /// apart and its last, a new line where it left the world and came back; none for one that never moved) and a circle
    /// of its body's radius where it ended, one group per creature titled with its id.
    /// </summary>
    private static void AddCreatures(XElement parent, WalkRecord record, float scale, Func<float, float, Vector2> place)
    {
        var creatures = new XElement(Svg + "g", new XAttribute("id", "creatures"), new XAttribute("stroke", CreatureColour), new XAttribute("fill", "none"));
        foreach (CreaturePath creature in record.Creatures.Where(c => c.Samples.Count > 0))
        {
            var group = new XElement(Svg + "g", new XAttribute("class", "creature"), new XAttribute("data-mover-id", $"0x{creature.Id:X8}"),
                new XElement(Svg + "title", Invariant($"creature 0x{creature.Id:X8}: {(creature.Creature.Wander > 0f ? $"wanders {creature.Creature.Wander} m about" : "stands at")} ({creature.Creature.Home.X}, {creature.Creature.Home.Y}), seed {creature.Creature.Seed}")));
            var line = new List<Vector2>();
            for (int i = 0; i < creature.Samples.Count; i++)
            {
                CreatureSample sample = creature.Samples[i];
                var at = new Vector2(sample.Position.X, sample.Position.Y);
                if (i > 0 && sample.Frame != creature.Samples[i - 1].Frame + 1)
                {
                    AddLine(); // it left the world and came back
                }

                if (line.Count == 0 || Vector2.Distance(at, line[^1]) >= CreaturePathSpacing || (i == creature.Samples.Count - 1 && at != line[^1]))
                {
                    line.Add(at);
                }
            }

            AddLine();
            Vector3 end = creature.Samples[^1].Position;
            Vector2 centre = place(end.X, end.Y);
            group.Add(new XElement(Svg + "circle", new XAttribute("class", "creature-body"), Attr("cx", centre.X), Attr("cy", centre.Y), Attr("r", MoverBody.Player.Radius * scale),
                new XAttribute("fill", CreatureColour), Attr("fill-opacity", 0.3f)));
            creatures.Add(group);

            // A line through the points gathered, when it went anywhere.
            void AddLine()
            {
                if (line.Count > 1)
                {
                    string points = string.Join(" ", line.Select(p => place(p.X, p.Y)).Select(p => Invariant($"{p.X:0.##},{p.Y:0.##}")));
                    group.Add(new XElement(Svg + "polyline", new XAttribute("class", "creature-path"), new XAttribute("points", points), Attr("stroke-width", 0.5f), Attr("stroke-opacity", 0.7f)));
                }

                line.Clear();
            }
        }

        parent.Add(creatures);
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
