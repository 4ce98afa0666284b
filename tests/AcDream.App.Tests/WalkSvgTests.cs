using System.Globalization;
using System.Numerics;
using System.Xml.Linq;
using AcDream.App.Scenes;
using AcDream.App.World;
using AcDream.Core.Physics;

namespace AcDream.App.Tests;

public class WalkSvgTests
{
    private static readonly XNamespace Svg = "http://www.w3.org/2000/svg";

    [Fact]
    public void Build_Floors_AreTheEnginesFloorTrianglesOfTheCells()
    {
        Scene scene = SceneReader.ReadDefault();
        HoltburgWorld world = scene.CreateWorld();
        WalkRecord record = SceneRunner.Run(scene, world, maxFrames: 1);
        var frame = new PhysicsEngine(HoltburgWorld.Holtburg);
        List<Vector3[]> expected = world.CellSurfaces
            .SelectMany(c => c.GetFloorTriangles().Select(t => new[] { t.A, t.B, t.C }.Select(v => frame.ToWorld(c.CellId, v)).ToArray()))
            .ToList();

        XDocument svg = WalkSvg.Build(record, world);

        List<Vector2[]> drawn = svg.Descendants(Svg + "g").Single(g => (string?)g.Attribute("id") == "floors")
            .Elements(Svg + "polygon").Select(p => Points((string)p.Attribute("points")!)).ToList();
        expected.Should().HaveCountGreaterThan(22, "every cell has floor triangles");
        drawn.Should().HaveCount(expected.Count, "one polygon per floor triangle the engine samples");
        drawn.Should().OnlyContain(p => p.Length == 3, "triangles");

        // The map is x' = a + s·x, y' = b − s·y (north up); fit it on two far-apart vertices, check every vertex.
        Vector3 first = expected[0][0];
        int far = expected.FindIndex(t => MathF.Abs(t[0].X - first.X) > 10f);
        far.Should().BePositive("the two buildings are more than 10 m apart");
        float scale = (drawn[far][0].X - drawn[0][0].X) / (expected[far][0].X - first.X);
        scale.Should().BePositive();
        float a = drawn[0][0].X - (scale * first.X), b = drawn[0][0].Y + (scale * first.Y);
        for (int i = 0; i < expected.Count; i++)
        {
            for (int k = 0; k < 3; k++)
            {
                var mapped = new Vector2(a + (scale * expected[i][k].X), b - (scale * expected[i][k].Y));
                Vector2.Distance(mapped, drawn[i][k]).Should().BeLessThan(0.05f, $"triangle {i} vertex {k}: engine {expected[i][k]} maps to {mapped}, drawn at {drawn[i][k]}");
            }
        }
    }

    [Fact]
    public void Build_WithABody_DrawsItsClearanceWhereItTouchedAWall()
    {
        var world = new HoltburgWorld();
        Scene scene = SceneReader.Parse("""
            { "name": "east wall", "start": { "position": [134, 5.15] }, "effects": "player",
              "legs": [ { "name": "in", "to": [137.2, 5.15] }, { "name": "room", "to": [139, 10] },
                        { "name": "into the east wall", "to": [152, 16], "seconds": 2.5 } ] }
            """, "test");
        WalkRecord record = SceneRunner.Run(scene, world);
        int[] touched = record.Samples.Where(s => s.Slide is { Z: 0f } || s.Refusal == ResolveOutcome.Wall).Select(s => s.Frame).ToArray();
        touched.Should().HaveCountGreaterThan(20, "the body slides along the east wall");

        XDocument svg = WalkSvg.Build(record, world);

        XElement[] circles = svg.Descendants(Svg + "g").Single(g => (string?)g.Attribute("id") == "body-clearance").Elements(Svg + "circle").ToArray();
        circles.Should().HaveCountGreaterThan(5);
        int[] frames = circles.Select(c => int.Parse(((string)c.Element(Svg + "title")!).Split(' ', ':')[1], CultureInfo.InvariantCulture)).ToArray();
        frames.Should().BeSubsetOf(touched, "a circle only where the engine answered a slide along a wall or a wall");
        frames.Should().Contain(touched[0]).And.BeInAscendingOrder();

        // The map is x' = a + s·x, y' = b − s·y: fit it on the first and last circles, then every circle
        // is centred on its frame's feet and its radius is the body's, 0.48 m, to that scale.
        Vector2 Centre(XElement c) => new(Number(c, "cx"), Number(c, "cy"));
        Vector3 p0 = record.Samples[frames[0]].Position, p1 = record.Samples[frames[^1]].Position;
        float scale = (Centre(circles[^1]).Y - Centre(circles[0]).Y) / (p0.Y - p1.Y);
        scale.Should().BeGreaterThan(1f, $"the slide runs north, from {p0} to {p1}");
        float a = Centre(circles[0]).X - (scale * p0.X), b = Centre(circles[0]).Y + (scale * p0.Y);
        for (int i = 0; i < circles.Length; i++)
        {
            Vector3 feet = record.Samples[frames[i]].Position;
            Vector2.Distance(Centre(circles[i]), new Vector2(a + (scale * feet.X), b - (scale * feet.Y))).Should().BeLessThan(0.05f, $"circle {i} (frame {frames[i]}) on the feet {feet}");
            Number(circles[i], "r").Should().BeApproximately(MoverBody.Player.Radius * scale, 0.01f, $"circle {i}: the body's radius at {scale} px per metre");
        }

        // The east wall (x = 142.1) is one radius from the centres: the circles touch it.
        float wall = a + (scale * 142.1f);
        circles.Where((c, i) => record.Samples[frames[i]].CellId == 0xA9B40143u && record.Samples[frames[i]].Slide is { X: < -0.99f })
            .Should().HaveCountGreaterThan(5, "the circles along the east wall").And.OnlyContain(c => MathF.Abs(Number(c, "cx") + Number(c, "r") - wall) < 0.05f, $"the east wall is drawn at x' = {wall}");
        svg.Descendants(Svg + "text").Select(t => t.Value).Should().Contain(t => t.StartsWith("body's clearance where it touched a wall", StringComparison.Ordinal), "the legend names the mark");

        XDocument point = WalkSvg.Build(SceneRunner.Run(scene with { Effects = MovementOptions.Player with { Body = null } }, world), world);
        point.Descendants(Svg + "g").Should().NotContain(g => (string?)g.Attribute("id") == "body-clearance", "a point mover has no body to draw");
    }

    [Fact]
    public void Build_DrawsTheCamerasEyeBesideTheRouteOnTheMapAndInTheProfile()
    {
        var world = new HoltburgWorld();
        Scene scene = SceneReader.Parse("""
            { "name": "eye", "start": { "position": [134, 5.15], "heading": 90 }, "effects": "player",
              "legs": [ { "name": "in", "to": [137.2, 5.15] }, { "name": "room", "to": [139, 10] }, { "name": "back into the east wall", "to": [142.5, 10], "backward": true, "seconds": 2 } ] }
            """, "test");
        WalkRecord record = SceneRunner.Run(scene, world);
        XDocument svg = WalkSvg.Build(record, world);
        XElement Group(string id) => svg.Descendants(Svg + "g").Single(g => (string?)g.Attribute("id") == id);

        // The map is x' = a + s·x, y' = b − s·y: fit it on the floors, as the engine has them.
        var frame = new PhysicsEngine(HoltburgWorld.Holtburg);
        Vector3[] corners = [.. world.CellSurfaces.SelectMany(c => c.GetFloorTriangles().Select(t => frame.ToWorld(c.CellId, t.A)))];
        Vector2[] drawnCorners = [.. Group("floors").Elements(Svg + "polygon").Select(p => Points((string)p.Attribute("points")!)[0])];
        int far = Array.FindIndex(corners, c => MathF.Abs(c.X - corners[0].X) > 10f);
        float scale = (drawnCorners[far].X - drawnCorners[0].X) / (corners[far].X - corners[0].X);
        float a = drawnCorners[0].X - (scale * corners[0].X), b = drawnCorners[0].Y + (scale * corners[0].Y);

        XElement eye = Group("map").Elements(Svg + "polyline").Single(l => (string?)l.Attribute("class") == "camera-eye");
        Vector2[] drawn = Points((string)eye.Attribute("points")!);
        Vector2[] eyes = [.. record.Samples.Select(s => new Vector2(a + (scale * s.Camera.Eye.X), b - (scale * s.Camera.Eye.Y)))];
        drawn.Length.Should().BeGreaterThan(20).And.BeLessThanOrEqualTo(eyes.Length);
        Vector2.Distance(drawn[0], eyes[0]).Should().BeLessThan(0.05f, "the line starts at the start's eye");
        Vector2.Distance(drawn[^1], eyes[^1]).Should().BeLessThan(0.05f, "and ends at the last frame's");
        int at = 0;
        foreach (Vector2 point in drawn)
        {
            while (at < eyes.Length && Vector2.Distance(point, eyes[at]) >= 0.05f)
            {
                at++;
            }

            at.Should().BeLessThan(eyes.Length, $"the point {point} is a frame's eye, in frame order");
        }

        string colour = (string)eye.Attribute("stroke")!;
        svg.Descendants(Svg + "polyline").Where(l => (string?)l.Attribute("class") != "camera-eye").Should().OnlyContain(l => (string?)l.Attribute("stroke") != colour, "a colour of its own");
        XElement height = Group("profile").Elements(Svg + "polyline").Single(l => (string?)l.Attribute("class") == "camera-eye");
        Points((string)height.Attribute("points")!).Should().HaveCount(record.Samples.Count, "the eye's Z at every frame");
        ((string)eye.Element(Svg + "title")!).Should().Be($"the chase camera's eye: {record.Samples.Count} frames, pulled in at {record.Samples.Count(s => s.Camera.PulledIn)}");
        record.Samples.Count(s => s.Camera.PulledIn).Should().BePositive("backing into the wall pulls it in");
        svg.Descendants(Svg + "text").Select(t => t.Value).Should().Contain(t => t.StartsWith("the chase camera's eye", StringComparison.Ordinal), "the legend names it");
    }

    [Fact]
    public void Build_HasScaleBarsAnInsetOfTheRoomsJumpAndLandingMarksAndTheCamerasBoom()
    {
        var world = new HoltburgWorld();
        Scene scene = SceneReader.Parse("""
            { "name": "marks", "start": { "position": [84, 5.15], "heading": 90 }, "effects": "player",
              "legs": [ { "name": "in", "to": [137.2, 5.15] }, { "name": "room", "to": [139, 10] }, { "name": "jump", "forward": 0, "seconds": 1.5, "jump": true } ] }
            """, "test");
        WalkRecord record = SceneRunner.Run(scene, world);
        XDocument svg = WalkSvg.Build(record, world);
        XElement Group(string id) => svg.Descendants(Svg + "g").Single(g => (string?)g.Attribute("id") == id);

        // A scale bar on the map and on the inset: a round number of metres, its length that many metres at the panel's scale.
        XElement[] bars = [.. svg.Descendants(Svg + "g").Where(g => (string?)g.Attribute("class") == "scale-bar")];
        bars.Should().HaveCount(2, "one on the map, one on the inset");
        foreach (XElement bar in bars)
        {
            float metres = Number(bar, "data-metres");
            new[] { 0.5f, 1f, 2f, 5f, 10f, 20f, 50f, 100f, 200f }.Should().Contain(metres);
            XElement line = bar.Elements(Svg + "line").First();
            float pixels = Number(line, "x2") - Number(line, "x1");
            (pixels / metres).Should().BeInRange(0.5f, 1000f);
            bar.Elements(Svg + "text").Single().Value.Should().Be(string.Create(CultureInfo.InvariantCulture, $"{metres:0.#} m"));
        }

        // The inset frames the rooms the route went through, closer than the map.
        XElement inset = Group("inset");
        inset.Descendants(Svg + "g").Should().Contain(g => (string?)g.Attribute("id") == "inset-floors");
        float Scale(XElement bar) => (Number(bar.Elements(Svg + "line").First(), "x2") - Number(bar.Elements(Svg + "line").First(), "x1")) / Number(bar, "data-metres");
        Scale(bars[1]).Should().BeGreaterThan(Scale(bars[0]), "the inset is closer than the map");
        svg.Descendants(Svg + "g").Count(g => (string?)g.Attribute("id") == "floors").Should().Be(1, "the inset's ids are its own");

        // A jump and its landing marked where they happened, on the map and on the inset.
        int jumps = record.Samples.Count(s => s.Moved.Jumps > 0), landings = record.Samples.Count(s => s.Moved.Landings > 0);
        (jumps, landings).Should().Be((1, 1), "one jump, one landing");
        foreach (string id in new[] { "air-marks", "inset-air-marks" })
        {
            XElement marks = svg.Descendants(Svg + "g").Single(g => (string?)g.Attribute("id") == id);
            marks.Elements(Svg + "polygon").Select(p => (string?)p.Attribute("class")).Should().BeEquivalentTo(["jump", "landing"], id);
        }

        // The camera's boom: a line from the player to the eye every 2 s, and the legend says what the eye's path is.
        XElement[] sights = [.. Group("camera-sights").Elements(Svg + "line")];
        sights.Should().HaveCount(record.Samples.Count(s => s.Frame % 60 == 0));
        svg.Descendants(Svg + "text").Select(t => t.Value).Should().Contain(t => t.Contains("the boom swinging as the player turns", StringComparison.Ordinal));
    }

    private static float Number(XElement element, string attribute) => float.Parse((string)element.Attribute(attribute)!, CultureInfo.InvariantCulture);

    private static Vector2[] Points(string points) =>
        points.Split(' ', StringSplitOptions.RemoveEmptyEntries)
            .Select(p => p.Split(','))
            .Select(xy => new Vector2(float.Parse(xy[0], CultureInfo.InvariantCulture), float.Parse(xy[1], CultureInfo.InvariantCulture)))
            .ToArray();
}
