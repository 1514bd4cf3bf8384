<?xml version="1.0" encoding="UTF-8"?>
<tileset version="1.8" tiledversion="1.8.2" name="terrain" tilewidth="32" tileheight="32" tilecount="4" columns="4">
 <image source="terrain.png" width="128" height="32"/>
  <tile id="0" type="ground">
   <properties>
    <property name="collider" type="bool" value="true"/>
   </properties>
  </tile>
  <tile id="1" type="brick">
   <objectgroup draworder="index" id="2">
    <object id="1" x="0" y="0" width="32" height="32"/>
   </objectgroup>
  </tile>
  <tile id="2" type="grass"/>
  <tile id="3" type="ladder">
   <properties>
    <property name="collider" type="bool" value="false"/>
   </properties>
  </tile>
</tileset>
